// Abaqus input file (.inp) export.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/export/export_options.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::io {

/// Writes an Abaqus .inp mesh: *HEADING (options.title), *NODE (ids =
/// 0-based index + 1), then per element block of detail::mesh_groups()
/// (the journal's <block>s, or by default one per volume in ascending id,
/// named volume_label(): volume name or "V<id>")
/// "*ELEMENT, TYPE=C3D8, ELSET=<name>" and/or "TYPE=C3D6"; element ids 1..
/// in that order (as in the Exodus file). A block with both hexes and
/// wedges gets element sets <name>_C3D8 and <name>_C3D6 and
/// "*ELSET, ELSET=<name>" naming both.
/// MeshDB hex/wedge node orders equal C3D8/C3D6 orders.
/// Node sets (<nodeset>s, by default one per meshed surface named
/// surface_<id>): "*NSET, NSET=<name>". Side sets of volume meshes
/// (<sideset>s, by default one per surface bounding a meshed volume, named
/// surface_<id>): "*ELSET, ELSET=<name>_S<k>" with the first-volume elements
/// whose face S<k> carries a surface element of the set's surfaces, and
/// "*SURFACE, TYPE=ELEMENT, NAME=<name>" listing those sets with their
/// face labels (C3D8: S1 = 1-2-3-4, S2 = 5-8-7-6, S3 = 1-5-6-2,
/// S4 = 2-6-7-3, S5 = 3-7-8-4, S6 = 4-8-5-1; C3D6: S1 = 1-2-3, S2 = 4-6-5,
/// S3 = 1-4-5-2, S4 = 2-5-6-3, S5 = 3-6-4-1).
/// Surface-only meshes: "*ELEMENT, TYPE=S4" / "TYPE=S3" per block (by
/// default per surface, ELSET=surface_<id>; with both types <name>_S4,
/// <name>_S3 and an *ELSET of both), plus the node sets.
/// Written atomically (see write_mesh()).
void write_inp(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options = {});

}  // namespace cooperage::io
