// Surface meshes as OpenMesh half-edge meshes (issue 19 item 5): the type
// handed to users who want to navigate, clean up or write a surface mesh
// with OpenMesh, and the conversion both ways. The schemes themselves work
// on index arrays (docs/design.md, "Arrays and OpenMesh").
// OpenMesh and OCCT must not meet in one translation unit (OCCT's Handle
// macro breaks OpenMesh's headers): only framework/geometry/occ includes
// OCCT, and nothing there includes this header.
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <vector>

namespace cooperage::om {

/// OpenMesh's default traits with double coordinates (the default float
/// would cut a mesh's coordinates to 7 digits).
struct SurfaceTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

/// A polygon mesh of quads and triangles.
using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<SurfaceTraits>;

/// Name of the int vertex property holding the MeshDB node (0-based) of each
/// vertex, and of the int face property holding the model surface id of
/// each face (to_openmesh adds both; from_openmesh reads them when present).
inline constexpr const char* kNodeProperty = "cooperage:node";
inline constexpr const char* kSurfaceProperty = "cooperage:surface";

/// Which surfaces to_openmesh takes.
enum class SurfaceSelection {
  All,       ///< every surface with elements (a surface mesh, --dim 2)
  Boundary,  ///< the surfaces with elements bounding exactly one meshed volume,
             ///< oriented out of it: the skin of a volume mesh
};

/// The quads and triangles of the selected surfaces as a half-edge mesh, in
/// ascending surface id, each surface's quads before its triangles. One
/// vertex per MeshDB node used (ascending node index), faces oriented as in
/// the MeshDB (Boundary: flipped where the meshed volume is the surface's
/// second). A face that would make an edge non-manifold (three faces on one
/// edge, as where the surfaces of an assembly meet) or join two faces of
/// opposite orientation gets its own copies of its vertices, as OpenMesh's
/// readers do; the copies carry the same node property.
/// @param[in] db    the mesh (0-based nodes)
/// @param[in] model its model (which volumes a surface bounds)
/// @param[in] which All or Boundary
SurfaceMesh to_openmesh(const mesh::MeshDB& db, const geom::Model& model,
                        SurfaceSelection which = SurfaceSelection::All);

/// A MeshDB holding `mesh` as surface elements: one node per vertex (in
/// vertex order, owned by the surface), each face a quad or triangle of the
/// surface in its kSurfaceProperty (or `surface_id` when the mesh has no
/// such property), in face order.
/// @throws MeshingError(InvalidInput) for a face with other than 3 or 4
///         vertices, naming the face.
mesh::MeshDB from_openmesh(const SurfaceMesh& mesh, int surface_id = 1);

}  // namespace cooperage::om
