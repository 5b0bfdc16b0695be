// The element blocks, side sets and node sets an export writes: the
// journal's <block>, <sideset>, <nodeset> (io::GroupSettings) resolved
// against a mesh, or the defaults where the journal names none.
// Internal to framework/io/export (namespace detail); not installed API.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>
#include <vector>

namespace cooperage::io::detail {

/// An element block: the elements of `entities` (volumes in a volume mesh,
/// surfaces in a surface-only mesh), ascending ids, each with elements.
struct MeshBlock {
  int id = 0;
  std::string name;
  std::vector<int> entities;
};

/// A side set: the volume-element faces on `surfaces` (ascending, each
/// with elements and a meshed first volume).
struct MeshSideSet {
  int id = 0;
  std::string name;
  std::vector<int> surfaces;
};

/// A node set: 0-based node indices, ascending, unique.
struct MeshNodeSet {
  int id = 0;
  std::string name;
  std::vector<int> nodes;
};

struct MeshGroups {
  bool volume_mesh = false;   ///< any hex or wedge (else the blocks are surfaces)
  bool named_blocks = false;  ///< blocks come from the journal
  bool named_side_sets = false;
  bool named_node_sets = false;
  std::vector<MeshBlock> blocks;
  std::vector<MeshSideSet> side_sets;  ///< none in a surface-only mesh
  std::vector<MeshNodeSet> node_sets;
};

/// Resolves options.groups against the mesh. Defaults, per kind the journal
/// leaves empty: a block per volume with elements (id = volume id, name
/// volume_label()), or per surface with elements in a surface-only mesh
/// (id = surface id, name "surface_<id>"); a side set per surface with
/// elements bounding a meshed volume (id = surface id, "surface_<id>"); a
/// node set per surface with elements (id = surface id, "surface_<id>").
/// Given blocks must cover every volume (surface-only mesh: surface) with
/// elements. Side sets are left out of a surface-only mesh.
/// @throws MeshingError(InvalidInput) naming the journal line: a block of
///         surfaces in a volume mesh (or of volumes in a surface mesh), a
///         volume with elements in no block, or a group none of whose
///         entities has elements (unless options.skip_empty_groups, when
///         such a group is left out).
MeshGroups mesh_groups(const mesh::MeshDB& db, const geom::Model& model,
                       const ExportOptions& options);

}  // namespace cooperage::io::detail
