// Where a volume's worst element lies and what bounds it, for a person. A
// hex or wedge below a scaled Jacobian of 0.2 is valid but poor (issue 16
// holds surfaces to that bar); the quality table gives its value only. At a
// corner of a face of angle a, or along an edge where two faces meet at a,
// no element exceeds sin(a), so a part with a 3-degree corner cannot do
// better there, and a larger or smaller size will not change it; elsewhere
// a smaller size or a cut often does.
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <string>

namespace cooperage::pipeline {

/// The scaled Jacobian below which a volume's worst element is explained.
inline constexpr double kPoorElement = 0.2;

/// A sentence on `volume`'s worst element when it is below `bar` and not
/// inverted (inverted elements are refused elsewhere), else empty: its
/// value, where it is (of elements within 1e-6 of the worst, the first in
/// the volume's order, so that a moved part names the moved element), and
/// either the corner of a face, or the convex edge between two faces, at
/// it that allows no better (sin of its angle), or that the part allows
/// more there.
std::string worst_element_note(const geom::Model& model, const mesh::MeshDB& db, int volume,
                               double bar = kPoorElement);

}  // namespace cooperage::pipeline
