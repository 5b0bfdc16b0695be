#include "framework/io/read/read_common.h"

#include "framework/core/error.h"
#include "framework/core/readable_file.h"

#include <fstream>
#include <sstream>

namespace cooperage::io::detail {

void parse_error(const std::string& path, const std::string& reason) {
  throw MeshingError(ErrorCode::ParseError, path + ": " + reason);
}

std::string read_text(const std::string& path) {
  require_readable_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshingError(ErrorCode::FileNotFound, path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void BlockCollector::add(const std::string& key, const std::string& name, quality::ElementType type,
                         const int* nodes) {
  auto [it, inserted] = index_.try_emplace({key, type}, blocks_.size());
  if (inserted) {
    MeshBlock b;
    b.name = name;
    b.type = type;
    blocks_.push_back(std::move(b));
  }
  auto& conn = blocks_[it->second].connectivity;
  conn.insert(conn.end(), nodes, nodes + quality::node_count(type));
}

}  // namespace cooperage::io::detail
