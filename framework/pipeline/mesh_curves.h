// Curve meshing: a node on every model vertex, then every curve's interior
// nodes placed by arc length on the true curve (uniform or biased spacing).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/mesh/curve_spacing.h"
#include "framework/mesh/mesh_db.h"

#include <map>

namespace cooperage::pipeline {

/// The spacing a journal asks for on a curve (uniform when not set).
mesh::CurveSpacing curve_spacing(const io::MeshSettings& settings, int curve_id);

/// Meshes every vertex and every curve of the model into `db` with the
/// given interval counts (curve id -> count). A curve with a size function
/// in `sizes` (IntervalSolution::sizes) and no spacing of its own places its
/// nodes by it. Deterministic: vertices, then curves, in id order.
void mesh_curves(const geom::Model& model, const std::map<int, int>& intervals,
                 const io::MeshSettings& settings, mesh::MeshDB& db,
                 const std::map<int, mesh::SizeFunction>* sizes = nullptr);

}  // namespace cooperage::pipeline
