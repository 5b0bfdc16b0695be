// Gmsh .msh 4.1 export, ASCII or binary.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::io {

/// Writes a Gmsh 4.1 file: ASCII ("$MeshFormat 4.1 0 8", numbers in their
/// shortest exact form), or with options.binary the binary variant ("4.1 1
/// 8", then the int 1; every number of $Entities, $Nodes and $Elements as a
/// raw int, size_t or double as the format specifies; $PhysicalNames stays
/// text). Gmsh and meshio read both; `cooperage quality` reads ASCII.
///
/// $PhysicalNames: the blocks and side sets of detail::mesh_groups()
/// (the journal's <block> and <sideset>, tag = id, their names): blocks of
/// dimension 3 (2 in a surface-only mesh), side sets of dimension 2; each
/// volume / surface entity lists the tags of the groups it is in. By
/// default one group per meshed volume (dim 3, tag = volume id, name =
/// volume_label(): the volume name or "V<id>") and one per meshed surface
/// (dim 2, tag = surface id, name "surface_<id>"). Node sets are not
/// written (Gmsh groups elements, not nodes).
/// $Entities: every vertex, curve, surface and volume of the model with its
/// bounding entities (signed by sense) and physical tag; boxes come from the
/// entity's nodes (falling back to the model's boxes).
/// $Nodes: grouped by the node owner (dim, id); a node whose owner is not an
/// entity of the model goes to the volume (else surface) of the first
/// element using it. Node tags are the 0-based index + 1.
/// $Elements: hexes (type 5) and prisms (type 6) per volume, then quads (3)
/// and triangles (2) per surface, of the entities in a physical group only
/// (as Gmsh writes them; meshio refuses elements outside every group when
/// groups exist); element tags 1.. in that order, so with the default blocks
/// the volume elements are numbered as in the Exodus file. Gmsh's linear hex and
/// prism node orders equal the MeshDB (Exodus) orders, so no permutation.
/// Written atomically (see write_mesh()).
void write_msh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options = {});

}  // namespace cooperage::io
