#include "framework/core/readable_file.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace cooperage {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary directory, removed after.
struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() / ("cooperage-readable-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

TEST(ReadableFile, ARegularFileIsReadable) {
  Scratch s;
  const fs::path f = s.dir / "part.step";
  std::ofstream(f) << "ISO-10303-21;";
  EXPECT_EQ(unreadable_file_reason(f.string()), "");
  EXPECT_NO_THROW(require_readable_file(f.string()));
}

TEST(ReadableFile, AMissingFileIsNamedAsMissing) {
  Scratch s;
  EXPECT_EQ(unreadable_file_reason((s.dir / "none.step").string()), "no such file");
}

TEST(ReadableFile, AFolderIsNotCalledMissing) {
  Scratch s;
  try {
    require_readable_file(s.dir.string());
    FAIL() << "a folder was accepted as a file";
  } catch (const MeshingError& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
    EXPECT_EQ(std::string(e.what()), s.dir.string() + ": is a directory, not a file");
  }
}

TEST(ReadableFile, APipeIsNotARegularFile) {
  Scratch s;
  const fs::path p = s.dir / "pipe.step";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  EXPECT_EQ(unreadable_file_reason(p.string()), "is not a regular file");
}

}  // namespace
}  // namespace cooperage
