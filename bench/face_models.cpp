#include "face_models.h"

#include "bench_models.h"
#include "framework/geometry/occ/workbench.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cooperage::bench {

namespace {

using geom::Vec3;

std::function<double(const geom::Curve&)> uniform(double size) {
  return [size](const geom::Curve&) { return size; };
}

void plate_with_holes(occ::Workbench& wb) {
  wb.brick("plate", {0, 0, 0}, {10, 6, 1});
  const double xs[] = {2.5, 5.0, 7.5};
  std::vector<std::string> inputs{"plate"};
  for (int i = 0; i < 3; ++i) {
    const std::string name = "hole" + std::to_string(i + 1);
    wb.cylinder(name, {xs[i], 3, -0.5}, {0, 0, 1}, 0.8, 2);
    inputs.push_back(name);
  }
  wb.cut("part", inputs);
}

/// The cylindrical surface of largest area.
int largest_cylinder(const geom::Model& model) {
  int best = 0;
  double best_area = 0;
  for (const auto& s : model.surfaces())
    if (s.geometry->type() == geom::SurfaceType::Cylinder && s.area > best_area) {
      best = s.id;
      best_area = s.area;
    }
  return best;
}

}  // namespace

int face_count() { return 8; }

geom::Model plate_three_holes() {
  occ::Workbench wb;
  plate_with_holes(wb);
  return wb.build_model();
}

BenchFace bench_face(int k, const std::string& brep_path) {
  occ::Workbench wb;
  BenchFace f;
  bool top = true;  // the face is the solid's top cap (else: its largest cylinder)
  switch (k) {
    case 0:
      f.name = "square";
      wb.brick("s", {0, 0, 0}, {10, 10, 1});
      f.size = uniform(0.25);
      break;
    case 1:
      f.name = "disk";
      wb.cylinder("s", {0, 0, 0}, {0, 0, 1}, 5, 1);
      f.size = uniform(0.25);
      break;
    case 2:
      f.name = "annulus";
      wb.cylinder("outer", {0, 0, 0}, {0, 0, 1}, 5, 1);
      wb.cylinder("inner", {0, 0, -0.5}, {0, 0, 1}, 2, 2);
      wb.cut("s", {"outer", "inner"});
      f.size = uniform(0.25);
      break;
    case 3:
      f.name = "plate_3_holes";
      plate_with_holes(wb);
      f.size = uniform(0.175);
      break;
    case 4:
      f.name = "L_shape";
      wb.prism("s", {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {4, 4, 0}, {4, 10, 0}, {0, 10, 0}}, {},
               {0, 0, 1});
      f.size = uniform(0.25);
      break;
    case 5:
      f.name = "dumbbell";
      wb.prism("s",
               {{0, 0, 0},
                {4, 0, 0},
                {4, 1.8, 0},
                {6, 1.8, 0},
                {6, 0, 0},
                {10, 0, 0},
                {10, 4, 0},
                {6, 4, 0},
                {6, 2.2, 0},
                {4, 2.2, 0},
                {4, 4, 0},
                {0, 4, 0}},
               {}, {0, 0, 1});
      f.size = uniform(0.2);  // the neck is 2 intervals across
      break;
    case 6:
      f.name = "cyl_patch";
      wb.revolve("s", {{2, 0, 0}, {5, 0, 0}, {5, 0, 3}, {2, 0, 3}}, {0, 0, 0}, {0, 0, 1}, 90);
      f.size = uniform(0.125);
      top = false;
      break;
    case 7:
      f.name = "graded_1to8";
      wb.brick("plate", {0, 0, 0}, {10, 10, 1});
      wb.cylinder("hole", {5, 5, -0.5}, {0, 0, 1}, 1, 2);
      wb.cut("s", {"plate", "hole"});
      f.size = [](const geom::Curve& c) {
        return c.geometry->type() == geom::CurveType::Circle ? 1.0 / 8 : 1.0;
      };
      break;
    default: throw std::out_of_range("bench_face: no face " + std::to_string(k));
  }
  if (!brep_path.empty()) wb.write(brep_path);
  f.model = wb.build_model();
  f.surface = top ? top_surface(f.model) : largest_cylinder(f.model);
  return f;
}

Loops2D unit_square_2d(int n) {
  std::vector<Eigen::Vector2d> loop;
  const Eigen::Vector2d corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < n; ++i)
      loop.push_back(corners[side] + (corners[(side + 1) % 4] - corners[side]) * i / n);
  return {loop};
}

Loops2D plate_with_holes_2d(int n) {
  Loops2D loops(1);
  const Eigen::Vector2d corners[] = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
  for (int side = 0; side < 4; ++side) {
    const int k = (side % 2 == 0 ? 4 : 2) * n;
    for (int i = 0; i < k; ++i)
      loops[0].push_back(corners[side] + (corners[(side + 1) % 4] - corners[side]) * i / k);
  }
  const double holes[3][3] = {{1.0, 1.0, 0.4}, {2.2, 1.0, 0.3}, {3.2, 0.8, 0.25}};
  for (const auto& h : holes) {
    const int k = 2 * std::max(2, static_cast<int>(std::lround(M_PI * h[2] * n)));  // even
    loops.emplace_back();
    for (int i = 0; i < k; ++i) {
      const double a = -2.0 * M_PI * i / k;  // clockwise
      loops.back().emplace_back(h[0] + h[2] * std::cos(a), h[1] + h[2] * std::sin(a));
    }
  }
  return loops;
}

}  // namespace cooperage::bench
