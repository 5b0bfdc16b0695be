#include "bench_models.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/solve.h"
#include "framework/pipeline/mesh_curves.h"
#include "schemes/builtin_schemes.h"

#include <vector>

namespace cooperage::bench {

geom::Model rectangle_plate(double w, double h) {
  occ::Workbench bench;
  bench.brick("plate", {0, 0, 0}, {w, h, 1});
  return bench.build_model();
}

geom::Model comb_prism(int teeth) {
  std::vector<geom::Vec3> profile{{0, 0, 0}, {2.0 * teeth - 1, 0, 0}};
  double x = 2.0 * teeth - 1;
  for (int t = 0; t < teeth; ++t) {  // walk back along the top edge
    profile.push_back({x, 4, 0});
    profile.push_back({x - 1, 4, 0});
    if (t + 1 < teeth) {
      profile.push_back({x - 1, 1, 0});
      profile.push_back({x - 2, 1, 0});
    }
    x -= 2;
  }
  occ::Workbench bench;
  bench.prism("comb", profile, {}, {0, 0, 1});
  return bench.build_model();
}

int top_surface(const geom::Model& model) {
  int best = 0;
  double best_z = -1e300;
  for (const auto& s : model.surfaces()) {
    const geom::Vec3 c = 0.5 * (s.box.min + s.box.max);
    const auto p = s.geometry->project(c);
    if (p.normal.z() > 0.99 && c.z() > best_z) {
      best = s.id;
      best_z = c.z();
    }
  }
  return best;
}

mesh::MeshDB curves_for_surface(const geom::Model& model, const scheme::SurfaceScheme& scheme,
                                int surface, double size) {
  intervals::IntervalProblem problem;
  for (const auto& c : model.curves()) problem.add_curve(c.id, c.length / size);
  scheme.constrain(scheme::SurfaceView{model, surface, nullptr}, problem);
  const auto solution = intervals::solve(problem);
  mesh::MeshDB db;
  pipeline::mesh_curves(model, solution.intervals, io::MeshSettings{}, db);
  return db;
}

mesh::MeshDB curves_for_surface(const geom::Model& model, const scheme::SurfaceScheme& scheme,
                                int surface,
                                const std::function<double(const geom::Curve&)>& size) {
  intervals::IntervalProblem problem;
  for (const auto& c : model.curves()) problem.add_curve(c.id, c.length / size(c));
  scheme.constrain(scheme::SurfaceView{model, surface, nullptr}, problem);
  const auto solution = intervals::solve(problem);
  mesh::MeshDB db;
  pipeline::mesh_curves(model, solution.intervals, io::MeshSettings{}, db);
  return db;
}

const scheme::Registry& builtin_registry() {
  static const scheme::Registry& registry = *[] {
    auto* r = new scheme::Registry;  // lives for the whole run
    register_builtin_schemes(*r);
    return r;
  }();
  return registry;
}

}  // namespace cooperage::bench
