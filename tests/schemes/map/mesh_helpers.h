// Test-only helpers around MeshDB: a uniform curve mesher, the commit of a
// scheme's EntityMesh, and element measures computed independently of the
// code under test (volume, scaled Jacobian, conformity).
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"
#include "framework/scheme/scheme.h"

#include <array>
#include <map>
#include <vector>

namespace cooperage::testing {

/// Meshes every vertex (one node, owner dim 0) and every curve of the model:
/// counts[curve] intervals, else max(1, round(length / size)), nodes at
/// uniform arc length (interior nodes owned by the curve).
void mesh_curves(const geom::Model& model, mesh::MeshDB& db, double size,
                 const std::map<int, int>& counts = {});

/// Adds the new nodes of `em` to db, owned by `owner`; returns local -> global.
std::vector<int> commit_nodes(mesh::MeshDB& db, const scheme::EntityMesh& em,
                              mesh::NodeOwner owner);
/// Commits a surface mesh (nodes + quads/tris, renumbered to global).
void commit_surface(mesh::MeshDB& db, int surface_id, const scheme::EntityMesh& em);
/// Commits a volume mesh (nodes + hexes, renumbered to global).
void commit_volume(mesh::MeshDB& db, int volume_id, const scheme::EntityMesh& em);

/// The 8 corner points of a hex.
std::array<geom::Vec3, 8> hex_points(const mesh::MeshDB& db, const mesh::Hex& hex);
/// Signed volume of a trilinear hex (divergence theorem, each face split along
/// both diagonals and averaged: exact for trilinear hexes).
double hex_volume(const std::array<geom::Vec3, 8>& x);
/// Min over the 8 corners of det(unit edge vectors) (Verdict hex scaled Jacobian).
double hex_scaled_jacobian(const std::array<geom::Vec3, 8>& x);
/// Min over the 4 corners of (e1 x e2).n / (|e1||e2|) with n the given normal.
double quad_scaled_jacobian(const mesh::MeshDB& db, const mesh::Quad& q, const geom::Vec3& normal);

/// Sorted node sets of the 6 faces of every hex, with their multiplicity.
std::map<std::array<int, 4>, int> hex_face_counts(const std::vector<mesh::Hex>& hexes);
/// Sorted node set of a quad.
std::array<int, 4> sorted(const mesh::Quad& q);

}  // namespace cooperage::testing
