// The fixed face set of the surface-scheme quality benchmarks (pave_bench.cpp,
// tri_bench.cpp) and of the Gmsh comparison (bench/peers/run_faces.py): each
// face is a face of a small OCCT solid, with a goal element size per curve.
#pragma once

#include "framework/geometry/model.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace cooperage::bench {

/// One benchmark face: the surface `surface` of `model`, meshed with interval
/// goals length / size(curve) on its curves.
struct BenchFace {
  std::string name;  ///< short id, e.g. "annulus"
  geom::Model model;
  int surface = 0;                                 ///< the face meshed
  std::function<double(const geom::Curve&)> size;  ///< goal size per curve [model units]
};

/// Number of faces in the set (BM_PaveFace/<k>, k in [0, face_count())).
int face_count();

/// Face k of the set: 0 square 10x10, 1 disk r=5, 2 annulus r=2..5,
/// 3 plate 10x6 with three holes r=0.8, 4 L-shape 10x10 (arms 4 wide),
/// 5 dumbbell (two 4x4 squares, a 2-long 0.4-wide neck), 6 cylindrical patch
/// (the r=5 face of a 90-degree revolve, 3 high), 7 square 10x10 at size 1 with
/// a round hole r=1 at size 1/8 (boundary spacing 1:8).
/// \param[in] k          face index
/// \param[in] brep_path  when not empty, the solid is also written there (BREP)
///                       so that another mesher can import the same geometry
BenchFace bench_face(int k, const std::string& brep_path = "");

/// The 10 x 6 x 1 plate with three through holes of radius 0.8 (the peers'
/// plate_three_holes); its top face is bench_face(3).surface.
geom::Model plate_three_holes();

/// Boundary loops of a 2D face for pave_2d (outer loop counter-clockwise,
/// holes clockwise), used by BM_Pave2D* and bench/pave_cleanup_table.cpp.
using Loops2D = std::vector<std::vector<Eigen::Vector2d>>;

/// The unit square with n boundary segments per side.
Loops2D unit_square_2d(int n);

/// The 4 x 2 plate with three round holes of the pave tests, n boundary
/// segments per unit length; each hole gets an even count.
Loops2D plate_with_holes_2d(int n);

}  // namespace cooperage::bench
