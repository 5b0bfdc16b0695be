#include "framework/pipeline/quality_report.h"

#include "framework/core/error.h"
#include "framework/geometry/projection_walk.h"
#include "framework/quality/evaluate.h"

#include <algorithm>
#include <array>

namespace cooperage::pipeline {
namespace {

using quality::ElementType;
using quality::Metric;

std::vector<Metric> metrics_for(ElementType type, const std::vector<io::QualityCheck>& checks) {
  std::vector<Metric> metrics{Metric::ScaledJacobian};
  for (const auto& c : checks) {
    const auto m = quality::metric_from_string(c.metric);
    if (!m) {
      throw MeshingError(ErrorCode::InvalidInput,
                         c.where.file + ":" + std::to_string(c.where.line) +
                             ": <quality>: unknown metric \"" + c.metric + "\"");
    }
    bool seen = false;
    for (Metric k : metrics) seen = seen || k == *m;
    if (!seen && quality::is_defined(*m, type)) metrics.push_back(*m);
  }
  return metrics;
}

// Normal of the surface at each element's centroid (for signed 2D metrics).
template <size_t N>
std::vector<Eigen::Vector3d> centroid_normals(const mesh::MeshDB& db, const geom::Surface& s,
                                              const std::vector<std::array<int, N>>& elements) {
  std::vector<Eigen::Vector3d> normals;
  normals.reserve(elements.size());
  geom::ProjectionWalk walk(*s.geometry);
  for (const auto& e : elements) {
    geom::Vec3 c = geom::Vec3::Zero();
    for (int n : e) c += db.node(n);
    c /= static_cast<double>(N);
    double reach = 0;  // a centroid lies within its element's size of the surface
    for (int n : e) reach = std::max(reach, (db.node(n) - c).norm());
    normals.push_back(walk.project(c, reach).normal);
  }
  return normals;
}

// Elements given as a vector of fixed-size node arrays, read in place.
template <size_t N>
void add_block(QualityReport& report, const mesh::MeshDB& db, int dim, int id, ElementType type,
               const std::vector<std::array<int, N>>& elements,
               const std::vector<Eigen::Vector3d>* normals,
               const std::vector<io::QualityCheck>& checks,
               const std::vector<double>* known_scaled_jacobian = nullptr) {
  if (elements.empty()) return;
  BlockReport block{dim, id, type, elements.size(), {}};
  quality::EvaluateOptions options;
  options.normals = normals;
  const bool known = known_scaled_jacobian && known_scaled_jacobian->size() == elements.size();
  for (Metric m : metrics_for(type, checks)) {
    const bool take = known && m == Metric::ScaledJacobian;
    std::vector<double> computed;
    if (!take) {
      computed = quality::evaluate(m, type, db.coords(), elements.front().data(), elements.size(),
                                   static_cast<int>(N), options);
    }
    const std::vector<double>& values = take ? *known_scaled_jacobian : computed;
    block.metrics.push_back(quality::summarize(m, values));
    // Each check counts against its own thresholds (one metric may be
    // checked twice, e.g. warn below 0.5 and fail below 0.2).
    for (size_t c = 0; c < checks.size(); ++c) {
      if (quality::metric_from_string(checks[c].metric) != m) continue;
      const auto s = quality::summarize(m, values, checks[c].min, checks[c].max);
      report.checks[c].violations += s.below_threshold;
    }
  }
  report.blocks.push_back(std::move(block));
}

const std::vector<double>* known_values(const std::map<int, std::vector<double>>& values, int id) {
  const auto it = values.find(id);
  return it == values.end() ? nullptr : &it->second;
}

}  // namespace

std::vector<Eigen::Vector3d> reference_normals(const mesh::MeshDB& db, const geom::Surface& surface,
                                               const std::vector<mesh::Quad>& quads) {
  return centroid_normals(db, surface, quads);
}

std::vector<Eigen::Vector3d> reference_normals(const mesh::MeshDB& db, const geom::Surface& surface,
                                               const std::vector<mesh::Tri>& tris) {
  return centroid_normals(db, surface, tris);
}

const quality::MetricSummary* BlockReport::find(const std::string& metric) const {
  for (const auto& m : metrics) {
    if (m.metric == metric) return &m;
  }
  return nullptr;
}

bool QualityReport::failed() const {
  for (const auto& c : checks) {
    if (c.failed) return true;
  }
  return false;
}

std::size_t QualityReport::inverted() const {
  std::size_t n = 0;
  for (const auto& b : blocks) {
    if (const auto* sj = b.find("scaled_jacobian")) n += sj->inverted;
  }
  return n;
}

QualityReport assess_quality(const mesh::MeshDB& db, const geom::Model& model,
                             const std::vector<io::QualityCheck>& checks,
                             const KnownScaledJacobians* known) {
  QualityReport report;
  for (const auto& c : checks) report.checks.push_back({c, 0, false});
  const bool volumes = db.hex_count() + db.wedge_count() > 0;
  if (volumes) {
    for (const auto& [id, v] : db.volumes()) {
      add_block(report, db, 3, id, ElementType::Hex, v.hexes, nullptr, checks,
                known ? known_values(known->hexes, id) : nullptr);
      add_block(report, db, 3, id, ElementType::Wedge, v.wedges, nullptr, checks,
                known ? known_values(known->wedges, id) : nullptr);
    }
  } else {
    for (const auto& [id, s] : db.surfaces()) {
      const geom::Surface& surface = model.surface(id);
      const auto qn = reference_normals(db, surface, s.quads);
      const auto tn = reference_normals(db, surface, s.tris);
      add_block(report, db, 2, id, ElementType::Quad, s.quads, &qn, checks);
      add_block(report, db, 2, id, ElementType::Tri, s.tris, &tn, checks);
    }
  }
  for (auto& c : report.checks) {
    c.failed = c.violations > 0 && c.check.action == io::QualityCheck::Action::Fail;
  }
  return report;
}

}  // namespace cooperage::pipeline
