// CurveGeometry over an OCCT edge. The evaluator holds only the immutable
// edge and builds its adaptor per call, so it is safe to share across threads.
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/shape_memo.h"

#include <BRepAdaptor_Curve.hxx>
#include <Extrema_ExtPC.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <memory>

namespace cooperage::occ::detail {
namespace {

/// parameter_at_length()'s answers per edge and thread, by the exact arc
/// length asked: the decomposition search plans every piece of every cut,
/// and the pieces' facts walk the solid's own blend curves at the same
/// lengths again (8 % of occt_CrankArm's refusal, tangent_departure.cpp).
/// 64 lengths an edge (a walk asks a few dozen; meshing a long curve asks
/// each node's once), 4,096 edges.
using ParametersAt = QueryMemo<double, double, 64>;
using KnownParameters = ShapeMemo<std::shared_ptr<ParametersAt>, 4096>;

geom::CurveType curve_type(GeomAbs_CurveType t) {
  switch (t) {
    case GeomAbs_Line: return geom::CurveType::Line;
    case GeomAbs_Circle: return geom::CurveType::Circle;
    case GeomAbs_Ellipse: return geom::CurveType::Ellipse;
    case GeomAbs_Hyperbola: return geom::CurveType::Hyperbola;
    case GeomAbs_Parabola: return geom::CurveType::Parabola;
    case GeomAbs_BezierCurve: return geom::CurveType::Bezier;
    case GeomAbs_BSplineCurve: return geom::CurveType::BSpline;
    case GeomAbs_OffsetCurve: return geom::CurveType::Offset;
    default: return geom::CurveType::Other;
  }
}

class EdgeCurve final : public geom::CurveGeometry {
 public:
  explicit EdgeCurve(const TopoDS_Edge& edge) : edge_(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD))) {
    const BRepAdaptor_Curve c(edge_);
    t0_ = c.FirstParameter();
    t1_ = c.LastParameter();
    type_ = curve_type(c.GetType());
    total_ = GCPnts_AbscissaPoint::Length(c, t0_, t1_);
  }

  geom::CurveType type() const override { return type_; }
  std::pair<double, double> range() const override { return {t0_, t1_}; }

  Vec3 point(double t) const override { return to_vec3(BRepAdaptor_Curve(edge_).Value(t)); }

  Vec3 tangent(double t) const override {
    gp_Pnt p;
    gp_Vec d;
    BRepAdaptor_Curve(edge_).D1(t, p, d);
    return to_vec3(d);
  }

  double length(double a, double b) const override {
    if (a == t0_ && b == t1_) return total_;
    if (b <= a) return 0.0;
    return GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge_), a, b);
  }

  double closest_parameter(const Vec3& p) const override {
    const BRepAdaptor_Curve c(edge_);
    const gp_Pnt q = to_pnt(p);
    double best_t = t0_;
    double best = c.Value(t0_).SquareDistance(q);
    const double d1 = c.Value(t1_).SquareDistance(q);
    if (d1 < best) {
      best = d1;
      best_t = t1_;
    }
    Extrema_ExtPC ext(q, c, t0_, t1_);
    if (ext.IsDone()) {
      for (int i = 1; i <= ext.NbExt(); ++i) {
        if (ext.SquareDistance(i) < best) {
          best = ext.SquareDistance(i);
          best_t = ext.Point(i).Parameter();
        }
      }
    }
    return std::clamp(best_t, t0_, t1_);
  }

  double parameter_at_length(double s) const override {
    if (s <= 0.0) return t0_;
    if (s >= total_) return t1_;
    std::shared_ptr<ParametersAt> at;  // this thread's, kept while in use
    if (const auto* known = KnownParameters::find(edge_)) {
      at = *known;
    } else {
      at = std::make_shared<ParametersAt>();
      KnownParameters::remember(edge_, at);
    }
    return at->answer(s, [&] { return parameter_at_length_uncached(s); });
  }

 private:
  double parameter_at_length_uncached(double s) const {
    const BRepAdaptor_Curve c(edge_);
    const double guess = t0_ + (t1_ - t0_) * s / total_;
    GCPnts_AbscissaPoint ap(c, s, t0_, guess);
    if (!ap.IsDone()) {
      GCPnts_AbscissaPoint ap2(c, s, t0_);
      return ap2.IsDone() ? std::clamp(ap2.Parameter(), t0_, t1_) : guess;
    }
    return std::clamp(ap.Parameter(), t0_, t1_);
  }

  TopoDS_Edge edge_;
  double t0_ = 0.0, t1_ = 0.0, total_ = 0.0;
  geom::CurveType type_ = geom::CurveType::Other;
};

}  // namespace

std::shared_ptr<const geom::CurveGeometry> make_curve_geometry(const TopoDS_Edge& edge) {
  return std::make_shared<EdgeCurve>(edge);
}

}  // namespace cooperage::occ::detail
