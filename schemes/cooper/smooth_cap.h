// Smoothing of the subcaps that form one exterior face (Blacker 1996,
// sec. 6.1: "a smooth of the independent subcaps forming an exterior face
// of the volume is performed to optimize element quality. Since this smooth
// does not affect the topology of the mesh, the structure of the ribs and
// barrel caps remains unaffected."). Value types only.
#pragma once

#include "framework/mesh/mesh_db.h"

#include <functional>
#include <vector>

namespace cooperage::cooper {

/// Minimum over the quads of the smallest corner sine, signed by the quad's
/// orientation about `normal` (1 for squares, <= 0 for inverted quads).
double min_quad_corner_quality(const std::vector<mesh::Vec3>& points,
                               const std::vector<mesh::Quad>& quads, const mesh::Vec3& normal);

/// The same over the corners of triangles (wedge and mixed caps).
double min_tri_corner_quality(const std::vector<mesh::Vec3>& points,
                              const std::vector<mesh::Tri>& tris, const mesh::Vec3& normal);

/// Laplacian smoothing of the `movable` nodes of a quad mesh, each step
/// followed by `project` (closest point on the face). The result is kept only
/// when the minimum corner quality does not drop; returns whether it was.
/// \param[in,out] points   node positions (indexed by the quads)
/// \param[in] normal       the face normal the quads are counter-clockwise about
bool smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                const std::vector<char>& movable, const mesh::Vec3& normal,
                const std::function<mesh::Vec3(const mesh::Vec3&)>& project, int iterations = 8);
/// The same for a mesh of quads and triangles (neither quality may drop).
bool smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                const std::vector<mesh::Tri>& tris, const std::vector<char>& movable,
                const mesh::Vec3& normal,
                const std::function<mesh::Vec3(const mesh::Vec3&)>& project, int iterations = 8);

/// Constrained ("smart") Laplacian smoothing: a movable node moves to the
/// (projected) mean of its neighbours only when the worst corner of the
/// faces around it does not get worse; node by node, in index order
/// (deterministic). For meshes folded or squashed next to a moved boundary,
/// where a plain Laplacian pulls nodes into a concave boundary. Returns
/// whether the worst corner over the mesh improved.
bool smart_smooth_cap(std::vector<mesh::Vec3>& points, const std::vector<mesh::Quad>& quads,
                      const std::vector<mesh::Tri>& tris, const std::vector<char>& movable,
                      const mesh::Vec3& normal,
                      const std::function<mesh::Vec3(const mesh::Vec3&)>& project,
                      int iterations = 40);

}  // namespace cooperage::cooper
