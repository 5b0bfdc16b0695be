// evaluate: one metric over many elements of a mesh given as a flat node
// coordinate array and a connectivity table, for callers with a mesh
// database (the quality report of every run, the `cooperage quality` app).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "framework/quality/metric.h"

namespace cooperage::quality {

/// Options of evaluate().
struct EvaluateOptions {
  /// Average element size for Metric::RelativeSize (volume for hexes, area
  /// for quads and tris, in the units of the coordinates). Unset: the mean
  /// of element_size() over the evaluated elements.
  std::optional<double> average_size;
  /// Optional reference normals, one per element (tris and quads only),
  /// e.g. the CAD surface normal at the element centroid. When given,
  /// scaled Jacobian, Jacobian and shape are signed against them, so an
  /// element inverted on its surface is reported negative / zero.
  const std::vector<Eigen::Vector3d>* normals = nullptr;
};

/// One metric of one element.
/// [in] nodes: node_count(type) points in Exodus/VTK order.
/// [in] normal: reference normal (tri/quad) or nullptr for the element's own.
/// [in] average_size: only read for Metric::RelativeSize.
/// Throws MeshingError(InvalidInput) if !is_defined(metric, type).
double evaluate_element(Metric metric, ElementType type, const Eigen::Vector3d* nodes,
                        const Eigen::Vector3d* normal = nullptr, double average_size = 0.0);

/// The size relative size compares: hex mean corner Jacobian (the volume of
/// a parallelepiped), quad and tri area; wedge: its Jacobian-free volume is
/// not needed (relative size is not defined for wedges) and 0 is returned.
double element_size(ElementType type, const Eigen::Vector3d* nodes);

/// `metric` for each of `count` elements.
/// [in] coords: node coordinates; connectivity indices are 0-based into it.
/// [in] connectivity: count * stride ints; element e uses
///      connectivity[e*stride .. e*stride + node_count(type) - 1]
///      (stride >= node_count(type), so 8-wide rows can hold any type).
/// [out] one value per element, in element order. The loop is plain and
/// deterministic; elements are independent, so callers may split the range.
/// Throws MeshingError(InvalidInput) for an undefined metric/type pair, a
/// stride smaller than the node count, an index out of range, or a normals
/// vector whose size differs from count.
std::vector<double> evaluate(Metric metric, ElementType type,
                             const std::vector<Eigen::Vector3d>& coords, const int* connectivity,
                             std::size_t count, int stride, const EvaluateOptions& options = {});

/// Convenience overload for 8-wide rows (hexes; other types use the first
/// node_count(type) entries of each row).
std::vector<double> evaluate(Metric metric, ElementType type,
                             const std::vector<Eigen::Vector3d>& coords,
                             const std::vector<std::array<int, 8>>& connectivity,
                             const EvaluateOptions& options = {});

}  // namespace cooperage::quality
