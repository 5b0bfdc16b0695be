#include "framework/pipeline/mesh_curves.h"

#include "framework/core/error.h"

namespace cooperage::pipeline {

mesh::CurveSpacing curve_spacing(const io::MeshSettings& settings, int curve_id) {
  mesh::CurveSpacing spacing;
  for (const io::CurveSetting& c : settings.curves) {
    if (c.id != curve_id) continue;
    switch (c.bias) {
      case io::BiasKind::None: spacing.kind = mesh::CurveSpacing::Kind::Uniform; break;
      case io::BiasKind::Geometric: spacing.kind = mesh::CurveSpacing::Kind::Geometric; break;
      case io::BiasKind::Dual: spacing.kind = mesh::CurveSpacing::Kind::Dual; break;
    }
    if (c.bias_ratio) spacing.ratio = *c.bias_ratio;
    spacing.first_size = c.bias_first_size;
    spacing.reverse = c.reverse_bias;
  }
  return spacing;
}

void mesh_curves(const geom::Model& model, const std::map<int, int>& intervals,
                 const io::MeshSettings& settings, mesh::MeshDB& db,
                 const std::map<int, mesh::SizeFunction>* sizes) {
  for (const geom::Vertex& v : model.vertices()) {
    if (db.vertex_node(v.id) < 0) {
      db.set_vertex_node(v.id, db.add_node(v.point, {0, v.id}));
    }
  }
  for (const geom::Curve& curve : model.curves()) {
    if (db.curve_meshed(curve.id)) continue;
    auto it = intervals.find(curve.id);
    if (it == intervals.end()) {
      throw MeshingError(ErrorCode::Internal, EntityRef::curve(curve.id), "no interval count");
    }
    const int n = it->second;
    std::vector<double> fractions;
    mesh::CurveSpacing spacing = curve_spacing(settings, curve.id);
    if (sizes != nullptr && spacing.kind == mesh::CurveSpacing::Kind::Uniform) {
      const auto sized = sizes->find(curve.id);
      if (sized != sizes->end()) {
        spacing.kind = mesh::CurveSpacing::Kind::Sized;
        spacing.sizes = sized->second;
      }
    }
    try {
      fractions = mesh::spacing_fractions(n, curve.length, spacing);
    } catch (const MeshingError& e) {
      throw MeshingError(e.code(), EntityRef::curve(curve.id), e.message());
    }
    const std::vector<double> t = mesh::parameters_at_fractions(*curve.geometry, fractions);
    std::vector<int> chain;
    chain.reserve(t.size());
    chain.push_back(db.vertex_node(curve.start_vertex));
    for (size_t i = 1; i + 1 < t.size(); ++i) {
      chain.push_back(db.add_node(curve.geometry->point(t[i]), {1, curve.id}));
    }
    chain.push_back(db.vertex_node(curve.end_vertex));
    db.set_curve_nodes(curve.id, std::move(chain));
  }
}

}  // namespace cooperage::pipeline
