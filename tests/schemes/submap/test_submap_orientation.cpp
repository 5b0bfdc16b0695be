// Orientation insensitivity of the submap scheme (Blacker 1996, sec. 1:
// "same mesh for transformed geometries"): a face meshed before and after a
// rigid transform of its model gives the same connectivity (local indices)
// and node positions related by the transform within 1e-9 x model size.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <functional>
#include <random>

#include "framework/geometry/occ/workbench.h"
#include "schemes/submap/submap_scheme.h"
#include "submap_face_run.h"

namespace cooperage::submap {
namespace {

using test::run_face;

/// A rigid transform x -> R (x - origin) + origin + shift, as the workbench
/// applies it (rotate, then translate).
struct Rigid {
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double angle_deg = 0.0;
  Vec3 shift = Vec3::Zero();

  Vec3 apply(const Vec3& x) const {
    const Eigen::AngleAxisd r(angle_deg * 3.14159265358979323846 / 180.0, axis.normalized());
    return r * (x - origin) + origin + shift;
  }
};

/// Hand-picked transforms (quarter turns of the plane, a half turn that flips
/// the face) and seeded random ones with non-axis-aligned axes.
std::vector<Rigid> transforms() {
  std::vector<Rigid> out;
  out.push_back({Vec3::Zero(), Vec3::UnitZ(), 90.0, Vec3(3, -2, 1)});
  out.push_back({Vec3(1, 2, 0), Vec3::UnitZ(), 180.0, Vec3::Zero()});
  out.push_back({Vec3::Zero(), Vec3::UnitX(), 180.0, Vec3(0, 0, 5)});
  out.push_back({Vec3::Zero(), Vec3(1, 1, 1), 120.0, Vec3::Zero()});
  out.push_back({Vec3::Zero(), Vec3::UnitZ(), 45.0, Vec3::Zero()});
  std::mt19937 rng(20240611u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 6; ++k) {
    Vec3 axis(u(rng), u(rng), u(rng));
    if (axis.norm() < 0.1) axis = Vec3(0.3, -0.7, 0.5);
    out.push_back({Vec3(u(rng), u(rng), u(rng)) * 3.0, axis, 180.0 * u(rng),
                   Vec3(u(rng), u(rng), u(rng)) * 20.0});
  }
  return out;
}

using Builder = std::function<void(occ::Workbench&)>;

geom::Model build(const Builder& make, const std::string& name, const Rigid* t) {
  occ::Workbench wb;
  make(wb);
  if (t) {
    wb.rotate(name, t->origin, t->axis, t->angle_deg);
    wb.translate(name, t->shift);
  }
  return wb.build_model();
}

/// Meshes every submappable surface `pick` selects in the model and its
/// transform; compares counts, connectivity and transformed coordinates.
void expect_orientation_insensitive(const Builder& make, const std::string& name,
                                    const std::function<bool(const geom::Surface&)>& pick,
                                    const std::vector<double>& sizes) {
  const auto scheme = make_submap();
  const geom::Model base = build(make, name, nullptr);
  const double tol = 1e-9 * base.box().diagonal();
  std::vector<int> faces;
  for (const auto& s : base.surfaces()) {
    if (pick(s) && scheme->applicable({base, s.id, nullptr}).ok) faces.push_back(s.id);
  }
  ASSERT_FALSE(faces.empty());
  const auto all = transforms();
  for (size_t k = 0; k < all.size(); ++k) {
    const Rigid& t = all[k];
    SCOPED_TRACE("transform " + std::to_string(k));
    const geom::Model moved = build(make, name, &t);
    // The transform keeps the ids: every vertex goes where it should.
    ASSERT_EQ(moved.vertices().size(), base.vertices().size());
    for (const auto& v : base.vertices()) {
      ASSERT_LT((t.apply(v.point) - moved.vertex(v.id).point).norm(),
                1e-7 * (1.0 + base.box().diagonal()));
    }
    for (int sid : faces) {
      for (double size : sizes) {
        SCOPED_TRACE("surface " + std::to_string(sid) + " size " + std::to_string(size));
        const auto a = run_face(base, sid, *scheme, size);
        const auto b = run_face(moved, sid, *scheme, size);
        ASSERT_EQ(a.solution.intervals, b.solution.intervals);
        ASSERT_EQ(a.mesh.coords.size(), b.mesh.coords.size());
        ASSERT_EQ(a.mesh.quads.size(), b.mesh.quads.size());
        EXPECT_EQ(a.mesh.quads, b.mesh.quads);
        EXPECT_EQ(a.mesh.global, b.mesh.global);
        double worst = 0.0;
        for (size_t n = 0; n < a.mesh.coords.size(); ++n) {
          worst = std::max(worst, (t.apply(a.mesh.coords[n]) - b.mesh.coords[n]).norm());
        }
        EXPECT_LE(worst, tol);
      }
    }
  }
}

std::vector<Vec3> polygon(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Vec3> out;
  for (const auto& q : xy) out.emplace_back(q[0], q[1], 0.0);
  return out;
}

bool planar(const geom::Surface& s) { return s.geometry->type() == geom::SurfaceType::Plane; }
bool holed(const geom::Surface& s) { return s.loops.size() > 1; }

TEST(SubmapOrientation, PlateWithOffCentreSquareHole) {
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.prism("p", polygon({{0, 0}, {10, 0}, {10, 8}, {0, 8}}),
                 {polygon({{6, 2}, {8, 2}, {8, 4}, {6, 4}})}, Vec3(0, 0, 1));
      },
      "p", holed, {1.0, 0.7, 0.45, 0.3, 0.55, 0.8, 1.3, 2.0});
}

TEST(SubmapOrientation, PlateWithCentredSquareHoleAtTiedOffsets) {
  // A centred hole with interval parities that put the least-squares
  // prediction at a half-integer offset: the tie must not depend on position.
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.prism("p", polygon({{0, 0}, {9, 0}, {9, 9}, {0, 9}}),
                 {polygon({{3.5, 3.5}, {5.5, 3.5}, {5.5, 5.5}, {3.5, 5.5}})}, Vec3(0, 0, 1));
      },
      "p", holed, {1.0, 0.5, 0.75, 1.5, 0.9});
}

TEST(SubmapOrientation, PlateWithRectangularHole) {
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.prism("p", polygon({{0, 0}, {10, 0}, {10, 8}, {0, 8}}),
                 {polygon({{2, 5}, {5, 5}, {5, 6}, {2, 6}})}, Vec3(0, 0, 1));
      },
      "p", holed, {1.0, 0.7, 0.45});
}

TEST(SubmapOrientation, LShapePrismAllFaces) {
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.prism("p", polygon({{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}), {},
                 Vec3(0, 0, 1.5));
      },
      "p", planar, {1.0, 0.45});
}

TEST(SubmapOrientation, CylinderSideWithNotch) {
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 4.0);
        wb.brick("b", Vec3(1.0, -0.8, 2.5), Vec3(3.0, 1.6, 2.0));
        wb.rotate("b", Vec3(0, 0, 0), Vec3(0, 0, 1), 90.0);
        wb.cut("n", {"c", "b"});
      },
      "n", [](const geom::Surface& s) { return s.geometry->type() == geom::SurfaceType::Cylinder; },
      {0.5, 0.3, 0.4});
}

TEST(SubmapOrientation, CylinderSideWithWindowHole) {
  // A hole on a curved face: its placement goes through the periodic
  // parameters of the side.
  expect_orientation_insensitive(
      [](occ::Workbench& wb) {
        wb.cylinder("c", Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, 4.0);
        wb.brick("b", Vec3(1.0, -0.8, 1.5), Vec3(3.0, 1.6, 1.0));
        wb.rotate("b", Vec3(0, 0, 0), Vec3(0, 0, 1), 150.0);
        wb.cut("w", {"c", "b"});
      },
      "w", [](const geom::Surface& s) { return s.geometry->type() == geom::SurfaceType::Cylinder; },
      {0.5, 0.35, 0.45});
}

}  // namespace
}  // namespace cooperage::submap
