// Models and helpers shared by the benchmarks.
#pragma once

#include "framework/geometry/model.h"
#include "framework/mesh/mesh_db.h"
#include "framework/scheme/registry.h"

#include <functional>
#include <map>
#include <string>

namespace cooperage::bench {

/// A plate w x h x 1 (its top face is a w x h rectangle).
geom::Model rectangle_plate(double w, double h);
/// A comb-shaped prism: `teeth` teeth of width 1 and depth 3 on a 1-thick spine.
geom::Model comb_prism(int teeth);
/// The surface of `model` whose outward normal at its centre is +z and that
/// lies highest (the top cap of a prism along z).
int top_surface(const geom::Model& model);
/// Meshes every curve of the model with goal length/size, the constraints of
/// `scheme` on `surface` applied (interval assignment by CBC).
mesh::MeshDB curves_for_surface(const geom::Model& model, const scheme::SurfaceScheme& scheme,
                                int surface, double size);
/// As above with a goal size per curve (interval goal = length / size(curve)).
mesh::MeshDB curves_for_surface(const geom::Model& model, const scheme::SurfaceScheme& scheme,
                                int surface, const std::function<double(const geom::Curve&)>& size);
/// The built-in schemes.
const scheme::Registry& builtin_registry();

}  // namespace cooperage::bench
