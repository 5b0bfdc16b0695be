// Helpers shared by the mesh file readers (read_mesh_file.h): errors that
// name the file, and a collector that groups elements into blocks.
#pragma once

#include "framework/core/readable_file.h"  // require_readable_file, for the readers
#include "framework/io/read/read_mesh_file.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::io::detail {

/// Throws MeshingError(ParseError, "<path>: <reason>").
[[noreturn]] void parse_error(const std::string& path, const std::string& reason);

/// The whole file as a string; FileNotFound if it cannot be opened.
std::string read_text(const std::string& path);

/// Groups elements into MeshBlocks by (key, type), in first-seen order.
class BlockCollector {
 public:
  /// Appends one element of `type` (node_count(type) 0-based indices) to
  /// the block of (key, type), creating it with `name` when new.
  void add(const std::string& key, const std::string& name, quality::ElementType type,
           const int* nodes);
  /// The blocks, in the order their first element was added.
  std::vector<MeshBlock> take() { return std::move(blocks_); }

 private:
  std::map<std::pair<std::string, quality::ElementType>, std::size_t> index_;
  std::vector<MeshBlock> blocks_;
};

/// Exodus / Gmsh wedge from a VTK_WEDGE (whose first triangle is wound the
/// other way): e[i] = vtk[{0, 2, 1, 3, 5, 4}[i]]; the map is its own inverse.
inline constexpr int kVtkWedgeToExodus[6] = {0, 2, 1, 3, 5, 4};

}  // namespace cooperage::io::detail
