#include "framework/quality/evaluate.h"

#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/quality/hex_metrics.h"
#include "framework/quality/quad_metrics.h"
#include "framework/quality/tri_metrics.h"
#include "framework/quality/wedge_metrics.h"

namespace cooperage::quality {

namespace {

using Eigen::Vector3d;

template <std::size_t N>
std::array<Vector3d, N> gather(const Vector3d* nodes) {
  std::array<Vector3d, N> a;
  for (std::size_t i = 0; i < N; ++i) a[i] = nodes[i];
  return a;
}

[[noreturn]] void invalid(const std::string& message) {
  throw MeshingError(ErrorCode::InvalidInput, "quality: " + message);
}

double hex_metric(Metric m, const HexNodes& p, double avg) {
  switch (m) {
    case Metric::ScaledJacobian: return hex_scaled_jacobian(p);
    case Metric::Jacobian: return hex_jacobian(p);
    case Metric::Skew: return hex_skew(p);
    case Metric::Taper: return hex_taper(p);
    case Metric::AspectFrobenius: return hex_max_aspect_frobenius(p);
    case Metric::EdgeRatio: return hex_edge_ratio(p);
    case Metric::Shape: return hex_shape(p);
    case Metric::RelativeSize: return hex_relative_size(p, avg);
  }
  return 0.0;
}

double wedge_metric(Metric m, const WedgeNodes& p) {
  switch (m) {
    case Metric::ScaledJacobian: return wedge_scaled_jacobian(p);
    case Metric::Jacobian: return wedge_jacobian(p);
    case Metric::AspectFrobenius: return wedge_max_aspect_frobenius(p);
    case Metric::EdgeRatio: return wedge_edge_ratio(p);
    case Metric::Shape: return wedge_shape(p);
    default: return 0.0;  // unreachable: checked by is_defined
  }
}

double quad_metric(Metric m, const QuadNodes& p, const Vector3d* n, double avg) {
  switch (m) {
    case Metric::ScaledJacobian: return n ? quad_scaled_jacobian(p, *n) : quad_scaled_jacobian(p);
    case Metric::Jacobian: return n ? quad_jacobian(p, *n) : quad_jacobian(p);
    case Metric::Skew: return quad_skew(p);
    case Metric::Taper: return quad_taper(p);
    case Metric::AspectFrobenius: return quad_max_aspect_frobenius(p);
    case Metric::EdgeRatio: return quad_edge_ratio(p);
    case Metric::Shape: return n ? quad_shape(p, *n) : quad_shape(p);
    case Metric::RelativeSize: return quad_relative_size(p, avg);
  }
  return 0.0;
}

double tri_metric(Metric m, const TriNodes& p, const Vector3d* n, double avg) {
  switch (m) {
    case Metric::ScaledJacobian: return n ? tri_scaled_jacobian(p, *n) : tri_scaled_jacobian(p);
    case Metric::Jacobian: return n ? tri_jacobian(p, *n) : tri_jacobian(p);
    case Metric::AspectFrobenius: return tri_aspect_frobenius(p);
    case Metric::EdgeRatio: return tri_edge_ratio(p);
    case Metric::Shape: return n ? tri_shape(p, *n) : tri_shape(p);
    case Metric::RelativeSize: return tri_relative_size(p, avg);
    default: return 0.0;  // unreachable: checked by is_defined
  }
}

}  // namespace

double evaluate_element(Metric metric, ElementType type, const Vector3d* nodes,
                        const Vector3d* normal, double average_size) {
  if (!is_defined(metric, type)) {
    invalid(std::string(to_string(metric)) + " is not defined for " + std::string(to_string(type)) +
            " elements");
  }
  switch (type) {
    case ElementType::Hex: return hex_metric(metric, gather<8>(nodes), average_size);
    case ElementType::Wedge: return wedge_metric(metric, gather<6>(nodes));
    case ElementType::Quad: return quad_metric(metric, gather<4>(nodes), normal, average_size);
    case ElementType::Tri: return tri_metric(metric, gather<3>(nodes), normal, average_size);
  }
  return 0.0;
}

double element_size(ElementType type, const Vector3d* nodes) {
  switch (type) {
    case ElementType::Hex: return hex_size(gather<8>(nodes));
    case ElementType::Quad: return quad_size(gather<4>(nodes));
    case ElementType::Tri: return tri_size(gather<3>(nodes));
    case ElementType::Wedge: return 0.0;
  }
  return 0.0;
}

std::vector<double> evaluate(Metric metric, ElementType type, const std::vector<Vector3d>& coords,
                             const int* connectivity, std::size_t count, int stride,
                             const EvaluateOptions& options) {
  if (!is_defined(metric, type)) {
    invalid(std::string(to_string(metric)) + " is not defined for " + std::string(to_string(type)) +
            " elements");
  }
  const int n = node_count(type);
  if (stride < n) {
    invalid("connectivity stride " + std::to_string(stride) + " is smaller than the " +
            std::to_string(n) + " nodes of a " + std::string(to_string(type)));
  }
  if (count > 0 && connectivity == nullptr) invalid("connectivity is null");
  if (options.normals && options.normals->size() != count) {
    invalid("normals has " + std::to_string(options.normals->size()) + " entries for " +
            std::to_string(count) + " elements");
  }

  // Validate every index first, so the parallel loop below cannot fail.
  const std::size_t width = static_cast<std::size_t>(stride);
  for (std::size_t e = 0; e < count; ++e) {
    for (int i = 0; i < n; ++i) {
      const int id = connectivity[e * width + static_cast<std::size_t>(i)];
      if (id < 0 || static_cast<std::size_t>(id) >= coords.size()) {
        invalid("element " + std::to_string(e) + " node " + std::to_string(i) + ": index " +
                std::to_string(id) + " out of range [0, " + std::to_string(coords.size()) + ")");
      }
    }
  }
  // One element's nodes, gathered on the fly (no copy of the whole mesh).
  auto nodes_of = [&](std::size_t e, Vector3d* out) {
    for (int i = 0; i < n; ++i) {
      out[i] =
          coords[static_cast<std::size_t>(connectivity[e * width + static_cast<std::size_t>(i)])];
    }
  };

  double average = 0.0;
  if (metric == Metric::RelativeSize) {
    if (options.average_size) {
      average = *options.average_size;
    } else if (count > 0) {
      double sum = 0.0;  // sequential sum: deterministic
      Vector3d buf[8];
      for (std::size_t e = 0; e < count; ++e) {
        nodes_of(e, buf);
        sum += element_size(type, buf);
      }
      average = sum / static_cast<double>(count);
    }
  }

  // Elements are independent: a parallel loop gives the same values as a
  // sequential one, whatever the thread count.
  std::vector<double> values(count);
  if (metric == Metric::ScaledJacobian && type == ElementType::Hex && stride == 8) {
    // Rows of exactly eight nodes: the batched kernel, the same bits.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        hex_scaled_jacobians(coords.data(), connectivity + 8 * range.begin(),
                                             range.size(), values.data() + range.begin());
                      });
    return values;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      Vector3d buf[8];
                      for (std::size_t e = range.begin(); e != range.end(); ++e) {
                        nodes_of(e, buf);
                        const Vector3d* normal = options.normals ? &(*options.normals)[e] : nullptr;
                        values[e] = evaluate_element(metric, type, buf, normal, average);
                      }
                    });
  return values;
}

std::vector<double> evaluate(Metric metric, ElementType type, const std::vector<Vector3d>& coords,
                             const std::vector<std::array<int, 8>>& connectivity,
                             const EvaluateOptions& options) {
  static_assert(sizeof(std::array<int, 8>) == 8 * sizeof(int), "rows are contiguous ints");
  return evaluate(metric, type, coords,
                  connectivity.empty() ? nullptr : connectivity.front().data(), connectivity.size(),
                  8, options);
}

}  // namespace cooperage::quality
