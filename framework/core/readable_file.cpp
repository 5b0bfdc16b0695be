#include "framework/core/readable_file.h"

#include "framework/core/error.h"

#include <filesystem>
#include <fstream>

namespace cooperage {

std::string unreadable_file_reason(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return "no such file";
  if (fs::is_directory(status)) return "is a directory, not a file";
  if (!fs::is_regular_file(status)) return "is not a regular file";
  if (!std::ifstream(path, std::ios::binary).good()) return "cannot be read (permission denied)";
  return "";
}

void require_readable_file(const std::string& path) {
  const std::string why = unreadable_file_reason(path);
  if (!why.empty()) throw MeshingError(ErrorCode::FileNotFound, path + ": " + why);
}

}  // namespace cooperage
