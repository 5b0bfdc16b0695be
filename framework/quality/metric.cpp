#include "framework/quality/metric.h"

#include <cmath>
#include <limits>

namespace cooperage::quality {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

std::string_view to_string(Metric metric) {
  switch (metric) {
    case Metric::ScaledJacobian: return "scaled_jacobian";
    case Metric::Jacobian: return "jacobian";
    case Metric::Skew: return "skew";
    case Metric::Taper: return "taper";
    case Metric::AspectFrobenius: return "aspect_frobenius";
    case Metric::EdgeRatio: return "edge_ratio";
    case Metric::Shape: return "shape";
    case Metric::RelativeSize: return "relative_size";
  }
  return "unknown";
}

std::optional<Metric> metric_from_string(std::string_view name) {
  for (Metric m : kAllMetrics) {
    if (to_string(m) == name) return m;
  }
  return std::nullopt;
}

std::string_view to_string(ElementType type) {
  switch (type) {
    case ElementType::Tri: return "tri";
    case ElementType::Quad: return "quad";
    case ElementType::Wedge: return "wedge";
    case ElementType::Hex: return "hex";
  }
  return "unknown";
}

std::optional<ElementType> element_type_from_string(std::string_view name) {
  for (ElementType t :
       {ElementType::Tri, ElementType::Quad, ElementType::Wedge, ElementType::Hex}) {
    if (to_string(t) == name) return t;
  }
  return std::nullopt;
}

int node_count(ElementType type) {
  switch (type) {
    case ElementType::Tri: return 3;
    case ElementType::Quad: return 4;
    case ElementType::Wedge: return 6;
    case ElementType::Hex: return 8;
  }
  return 0;
}

bool higher_is_better(Metric metric) {
  switch (metric) {
    case Metric::ScaledJacobian:
    case Metric::Jacobian:
    case Metric::Shape:
    case Metric::RelativeSize: return true;
    case Metric::Skew:
    case Metric::Taper:
    case Metric::AspectFrobenius:
    case Metric::EdgeRatio: return false;
  }
  return true;
}

bool is_defined(Metric metric, ElementType type) {
  switch (type) {
    case ElementType::Hex:
    case ElementType::Quad: return true;
    case ElementType::Wedge:
      return metric != Metric::Skew && metric != Metric::Taper && metric != Metric::RelativeSize;
    case ElementType::Tri: return metric != Metric::Skew && metric != Metric::Taper;
  }
  return false;
}

std::optional<Range> acceptable_range(Metric metric, ElementType type) {
  if (!is_defined(metric, type)) return std::nullopt;
  switch (type) {
    case ElementType::Hex:  // Verdict manual, hexahedral metrics table
      switch (metric) {
        case Metric::ScaledJacobian: return Range{0.5, 1.0};
        case Metric::Jacobian: return Range{0.0, kInf};
        case Metric::Skew: return Range{0.0, 0.5};
        case Metric::Taper: return Range{0.0, 0.5};
        case Metric::AspectFrobenius: return Range{1.0, 3.0};
        case Metric::EdgeRatio: return std::nullopt;
        case Metric::Shape: return Range{0.3, 1.0};
        case Metric::RelativeSize: return Range{0.5, 1.0};
      }
      break;
    case ElementType::Quad:  // Verdict manual, quadrilateral metrics table
      switch (metric) {
        case Metric::ScaledJacobian: return Range{0.3, 1.0};
        case Metric::Jacobian: return Range{0.0, kInf};
        case Metric::Skew: return Range{0.0, 0.5};
        case Metric::Taper: return Range{0.0, 0.7};
        case Metric::AspectFrobenius: return Range{1.0, 1.3};
        case Metric::EdgeRatio: return Range{1.0, 1.3};
        case Metric::Shape: return Range{0.3, 1.0};
        case Metric::RelativeSize: return Range{0.3, 1.0};
      }
      break;
    case ElementType::Tri:  // Verdict manual, triangle metrics table
      switch (metric) {
        case Metric::ScaledJacobian: return Range{0.5, 2.0 / std::sqrt(3.0)};
        case Metric::Jacobian: return Range{0.0, kInf};
        case Metric::AspectFrobenius: return Range{1.0, 1.3};
        case Metric::EdgeRatio: return Range{1.0, 1.3};
        case Metric::Shape: return Range{0.25, 1.0};
        case Metric::RelativeSize: return Range{0.25, 1.0};
        default: return std::nullopt;
      }
    case ElementType::Wedge:  // Verdict publishes few; Cubit's general ranges
      switch (metric) {
        case Metric::ScaledJacobian: return Range{0.5, 1.0};
        case Metric::Jacobian: return Range{0.0, kInf};
        case Metric::Shape: return Range{0.3, 1.0};
        default: return std::nullopt;
      }
  }
  return std::nullopt;
}

std::optional<Range> natural_range(Metric metric) {
  switch (metric) {
    case Metric::ScaledJacobian: return Range{-1.0, 1.0};
    case Metric::Skew:
    case Metric::Shape:
    case Metric::RelativeSize: return Range{0.0, 1.0};
    default: return std::nullopt;
  }
}

Range attainable_range(Metric metric) {
  switch (metric) {
    case Metric::Taper: return Range{0.0, kInf};
    case Metric::AspectFrobenius:
    case Metric::EdgeRatio: return Range{1.0, kInf};
    case Metric::Jacobian: return Range{-kInf, kInf};
    default: return *natural_range(metric);
  }
}

}  // namespace cooperage::quality
