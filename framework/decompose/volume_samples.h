// Points on the boundary of a volume (its vertices and points along its
// curves), the cheap stand-in for its shape when the decomposition asks on
// which side of a cutting surface a volume lies and how thick a piece is.
#pragma once

#include "framework/geometry/model.h"

#include <vector>

namespace cooperage::decompose {

/// The curves bounding a volume (every loop of every surface), ascending.
std::vector<int> curves_of(const geom::Model& model, int volume);

/// Unit normals out of `volume` of its faces along `curve`, at the curve's
/// parameter midpoint: two at an edge between two of its faces, one at a
/// seam (faces of other volumes are left out).
std::vector<geom::Vec3> outward_normals_at(const geom::Model& model, int volume, int curve);

/// Points inside each curve that stand for it (occ::SolidPieces::
/// boundary_samples takes as many from a solid's edges).
constexpr int kSamplesPerCurve = 7;

/// The vertices of the volume, then `per_curve` points inside each of its
/// curves (evenly in parameter), in curve id order.
std::vector<geom::Vec3> volume_samples(const geom::Model& model, int volume,
                                       int per_curve = kSamplesPerCurve);

}  // namespace cooperage::decompose
