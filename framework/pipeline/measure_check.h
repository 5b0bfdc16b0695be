// Never a silently wrong mesh (issue 21 item 3b, issue 16 item 4): the
// meshed volume of every volume (3D) or area of every surface (2D) against
// the CAD's. An invalid B-rep was once meshed at 44 % less volume than the
// CAD with exit 0; this check catches any such loss, whatever its cause.
//
// Elements have straight edges and (bi)linear faces, so a round face meshed
// at a coarse size loses the sliver between its facets and the surface
// (17 % of a rod meshed as a hexagon). That sliver is not an error: it is
// computed from the mesh itself and credited before comparing. For a facet
// over a surface that is quadratic across it, the gap g between facet and
// surface vanishes at the facet's corners, and
//   - its mean over a (bi)linear quad is 2/3 of its value at the centre,
//     over a triangle 3/4 of its value at the centroid (exact for any
//     quadratic surface over a parallelogram or triangle);
//   - a surface's area over a facet (2D) is estimated by splitting the
//     facet in four with the new nodes on the surface (edge midpoints on
//     their model curve at the boundary, on the surface inside; a quad's
//     centre on the surface): facet areas converge as h^2, so the area is
//     A_h/2 + (A_h/2 - A_h) / 3 (Richardson). This covers curved faces and
//     chords of curved boundaries alike; a first-order formula in the
//     slopes (8/3 (g/L)^2) over-credited coarse facets on B-spline faces by
//     up to 5 % of their area and failed good meshes. Only facets whose
//     corners lie on the surface are credited (a mesh off its surface is
//     never excused). Far coarser than h^2 behaviour (a ball as 20
//     triangles) the estimate stays a few % short and the check fails.
// Each gap is capped at 0.3 of the facet's size (an arc of 120 degrees per
// element), so that a facet far from its surface is not excused as faceting.
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <vector>

namespace cooperage::pipeline {

struct MeasureCheck {
  EntityRef entity;     ///< a volume (3D meshes) or a surface (surface meshes)
  double cad = 0;       ///< the CAD's volume or area
  double mesh = 0;      ///< the sum over the entity's elements
  double faceting = 0;  ///< what facets over curved geometry leave out (see above)
  /// |mesh + faceting - cad| / cad.
  double deviation() const;
};

/// One check per meshed volume with elements (when the mesh has volume
/// elements), otherwise per meshed surface with elements; in id order.
/// Runs in parallel over entities; the result does not depend on threads.
std::vector<MeasureCheck> compare_measures(const geom::Model& model, const mesh::MeshDB& db);

/// Volume of a hexahedron (Exodus node order), exact for the trilinear map
/// (closed form); negative when inverted.
double hex_volume(const std::array<geom::Vec3, 8>& x);
/// Volume of a wedge (Exodus node order), exact for its linear-by-linear map.
double wedge_volume(const std::array<geom::Vec3, 6>& x);

}  // namespace cooperage::pipeline
