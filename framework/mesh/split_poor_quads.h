// Quad-dominant meshes from quad meshes: every quad whose scaled Jacobian is
// below a threshold is split into two triangles, the rest stay quads, so
// triangles appear exactly where a quad would be poor (Blacker 1996,
// abstract: "a wedge/hexahedral element mix ... by simply allowing ...
// mixed triangle/quadrilateral cap meshes"). A split adds no node and
// changes no edge of the quad's boundary, so the mesh stays conformal with
// its neighbours (curves, side faces, sweeps through the cap).
#pragma once

#include "framework/mesh/corner_sine.h"
#include "framework/mesh/mesh_db.h"

#include <array>
#include <vector>

namespace cooperage::mesh {

/// The quads kept (in input order, then the merged ones) and the triangles.
struct QuadDominant {
  std::vector<Quad> quads;
  std::vector<Tri> tris;
};

/// Quad (a, b, c, d) split along the diagonal that makes the smaller of the
/// two triangles' min_corner_sine largest: at a sharp corner the diagonal
/// not through it (which would halve the sharp angle). Ties (within 1e-9)
/// take a-c, so a rigidly moved quad splits the same way.
std::array<Tri, 2> split_quad(const std::vector<Vec3>& points, const Quad& q);

/// Splits every quad whose scaled Jacobian (min_corner_sine about the quad's
/// own centre normal, Verdict's quad normal) is below `min_quality` with
/// split_quad(); the others are kept. Then two neighbouring triangles of
/// different split quads that make a quad of at least `min_quality` are
/// merged into it (best quad first), so no two triangles left would make a
/// good quad. Deterministic; qualities compared after rounding to 1e-9, so
/// a rigidly moved mesh gives the same elements.
/// \param[in] points       node positions, indexed by the quads
/// \param[in] quads        counter-clockwise about the surface normal
/// \param[in] min_quality  the smallest scaled Jacobian a kept quad has, in (0, 1]
QuadDominant split_poor_quads(const std::vector<Vec3>& points, const std::vector<Quad>& quads,
                              double min_quality);

}  // namespace cooperage::mesh
