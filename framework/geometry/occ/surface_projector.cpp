#include "framework/geometry/occ/surface_projector.h"

#include <ElSLib.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace cooperage::occ::detail {
namespace {

using geom::Vec2;

// Shifts x by whole periods into [lo - slack, lo - slack + period).
double into_period(double x, double lo, double period, double slack) {
  const double base = lo - slack;
  return x - period * std::floor((x - base) / period);
}

}  // namespace

SurfaceProjector::SurfaceProjector(const Handle(Geom_Surface) & surface, double u0, double u1,
                                   double v0, double v1)
    : surface_(surface), u0_(u0), u1_(u1), v0_(v0), v1_(v1) {
  const GeomAdaptor_Surface a(surface_);
  switch (a.GetType()) {
    case GeomAbs_Plane:
      kind_ = Kind::Plane;
      plane_ = a.Plane();
      break;
    case GeomAbs_Cylinder:
      kind_ = Kind::Cylinder;
      cylinder_ = a.Cylinder();
      break;
    case GeomAbs_Cone:
      kind_ = Kind::Cone;
      cone_ = a.Cone();
      break;
    case GeomAbs_Sphere:
      kind_ = Kind::Sphere;
      sphere_ = a.Sphere();
      break;
    case GeomAbs_Torus:
      kind_ = Kind::Torus;
      torus_ = a.Torus();
      break;
    default: kind_ = Kind::Other; break;
  }
  u_periodic_ = surface_->IsUPeriodic();
  v_periodic_ = surface_->IsVPeriodic();
  if (u_periodic_) u_period_ = surface_->UPeriod();
  if (v_periodic_) v_period_ = surface_->VPeriod();
  // Size of the face from its corners and centre (for 3D tolerances).
  const gp_Pnt c[5] = {surface_->Value(u0, v0), surface_->Value(u1, v0), surface_->Value(u0, v1),
                       surface_->Value(u1, v1), surface_->Value(0.5 * (u0 + u1), 0.5 * (v0 + v1))};
  double s = 0.0;
  for (int i = 0; i < 5; ++i) {
    for (int j = i + 1; j < 5; ++j) s = std::max(s, c[i].Distance(c[j]));
  }
  scale_ = std::max(s, 1e-6);
}

bool SurfaceProjector::in_box(Vec2& uv) const {
  const double su = 1e-9 * std::max(1.0, std::abs(u1_ - u0_));
  const double sv = 1e-9 * std::max(1.0, std::abs(v1_ - v0_));
  if (u_periodic_) uv.x() = into_period(uv.x(), u0_, u_period_, su);
  if (v_periodic_) uv.y() = into_period(uv.y(), v0_, v_period_, sv);
  if (uv.x() < u0_ - su || uv.x() > u1_ + su || uv.y() < v0_ - sv || uv.y() > v1_ + sv)
    return false;
  uv.x() = std::clamp(uv.x(), u0_, u1_);
  uv.y() = std::clamp(uv.y(), v0_, v1_);
  return true;
}

std::optional<Vec2> SurfaceProjector::closed_form(const gp_Pnt& p,
                                                  std::optional<Vec2>* outside) const {
  if (kind_ == Kind::Other) return std::nullopt;
  double u = 0.0, v = 0.0;
  switch (kind_) {
    case Kind::Plane: ElSLib::Parameters(plane_, p, u, v); break;
    case Kind::Cylinder: {
      // On the axis every angle is closest: leave the choice to the global search.
      const gp_Cylinder& c = cylinder_;
      if (gp_Lin(c.Axis()).Distance(p) < 1e-9 * c.Radius()) return std::nullopt;
      ElSLib::Parameters(c, p, u, v);
      break;
    }
    case Kind::Cone: {
      const gp_Cone& c = cone_;
      if (gp_Lin(c.Axis()).Distance(p) < 1e-9 * scale_) return std::nullopt;
      ElSLib::Parameters(c, p, u, v);
      // ElSLib gives the foot on the generatrix at the point's angle, the
      // closest point while it does not lie beyond the apex.
      if (c.RefRadius() + v * std::sin(c.SemiAngle()) < 0.0) return std::nullopt;
      break;
    }
    case Kind::Sphere: {
      const gp_Sphere& s = sphere_;
      if (s.Location().Distance(p) < 1e-9 * s.Radius()) return std::nullopt;
      ElSLib::Parameters(s, p, u, v);
      break;
    }
    case Kind::Torus: {
      const gp_Torus& t = torus_;
      if (gp_Lin(t.Axis()).Distance(p) < 1e-9 * t.MajorRadius()) return std::nullopt;
      ElSLib::Parameters(t, p, u, v);
      break;
    }
    case Kind::Other: return std::nullopt;
  }
  Vec2 uv(u, v);
  if (!std::isfinite(u) || !std::isfinite(v)) return std::nullopt;
  if (in_box(uv)) return uv;
  // A foot a hair outside the face's box (a B-spline rim node within its
  // fitting error of an analytic face) is the box's nearest point. Further
  // out, the box point nearest the foot is a candidate the caller weighs
  // against the bounded global search, which misses a minimum on the box's
  // edge and can return the farthest stationary point instead (the
  // antipode on a sphere).
  const gp_Pnt foot = surface_->Value(u, v);
  Vec2 clamped(std::clamp(uv.x(), u0_, u1_), std::clamp(uv.y(), v0_, v1_));
  if (surface_->Value(clamped.x(), clamped.y()).Distance(foot) <= 1e-6 * scale_) return clamped;
  if (outside) *outside = clamped;
  return std::nullopt;
}

std::optional<Vec2> SurfaceProjector::newton(const gp_Pnt& p, const Vec2& hint) const {
  if (!std::isfinite(hint.x()) || !std::isfinite(hint.y())) return std::nullopt;
  double u = std::clamp(hint.x(), u0_, u1_), v = std::clamp(hint.y(), v0_, v1_);
  // A full Newton step of length d leaves an error of order d^2 / scale:
  // after one of 1e-8 the point is exact to rounding, and the step that
  // would prove it (another D2, the cost of a projection) is not taken.
  const double converged = 1e-8 * scale_;
  gp_Pnt s;
  gp_Vec su, sv, suu, svv, suv;
  try {
    const GeomAdaptor_Surface& adaptor = evaluator();
    for (int it = 0; it < 30; ++it) {
      adaptor.D2(u, v, s, su, sv, suu, svv, suv);
      const gp_Vec r(p, s);  // S - p
      const double g0 = r.Dot(su), g1 = r.Dot(sv);
      // Hessian of |S - p|^2 / 2; Gauss-Newton's J^T J when it is not
      // positive definite (far from the minimum on a strongly curved face).
      double h00 = su.Dot(su) + r.Dot(suu), h01 = su.Dot(sv) + r.Dot(suv),
             h11 = sv.Dot(sv) + r.Dot(svv);
      double det = h00 * h11 - h01 * h01;
      const bool full = h00 > 0.0 && det > 1e-14 * h00 * h11;
      if (!full) {
        h00 = su.Dot(su);
        h01 = su.Dot(sv);
        h11 = sv.Dot(sv);
        det = h00 * h11 - h01 * h01;
        if (!(h00 > 0.0 && det > 1e-14 * h00 * h11)) return std::nullopt;  // singular point
      }
      const double du = -(h11 * g0 - h01 * g1) / det;
      const double dv = -(h00 * g1 - h01 * g0) / det;
      const double un = std::clamp(u + du, u0_, u1_), vn = std::clamp(v + dv, v0_, v1_);
      const double moved = (su * (un - u) + sv * (vn - v)).Magnitude();
      if (!std::isfinite(moved)) return std::nullopt;
      const bool clamped = un != u + du || vn != v + dv;
      u = un;
      v = vn;
      // Accepted: a full step inside the box of at most `converged`, or a
      // step that stalled on the box's edge. Either way a minimum: the
      // Hessian just used is positive definite (Gauss-Newton's is not
      // proof) and the gradient vanishes to the step's accuracy. A point
      // on the edge of a non-periodic direction is a constrained minimum,
      // which the global search decides, unless it lies on the surface to
      // within a CAD tolerance (1e-6 of the face): a node of the face's own
      // boundary curve, which no other point of the face can be closer to by
      // more than that (the global search cost 50-100 us a node).
      const bool stalled = moved <= 1e-12 * scale_;
      if ((full && !clamped && moved <= converged) || stalled) {
        if (!full) return std::nullopt;
        const bool edge_u = (u <= u0_ || u >= u1_) && !u_periodic_;
        const bool edge_v = (v <= v0_ || v >= v1_) && !v_periodic_;
        const double distance = r.Magnitude();
        if ((edge_u || edge_v) && stalled && distance <= 1e-6 * scale_) return Vec2(u, v);
        const double ref = std::max(distance, scale_) * std::max(su.Magnitude(), sv.Magnitude());
        if (std::hypot(g0, g1) > (stalled ? 1e-8 : 1e-6) * ref) return std::nullopt;
        if ((edge_u || edge_v) && distance > 1e-9 * scale_) return std::nullopt;
        return Vec2(u, v);
      }
    }
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
  return std::nullopt;
}

const GeomAdaptor_Surface& SurfaceProjector::evaluator() const {
  auto& a = adaptors_.local();
  if (!a) a = std::make_unique<GeomAdaptor_Surface>(surface_, u0_, u1_, v0_, v1_);
  return *a;
}

void SurfaceProjector::d1(double u, double v, gp_Pnt& p, gp_Vec& su, gp_Vec& sv) const {
  // An elementary surface's own formula, as its Geom_ class evaluates it.
  switch (kind_) {
    case Kind::Plane: ElSLib::D1(u, v, plane_, p, su, sv); return;
    case Kind::Cylinder: ElSLib::D1(u, v, cylinder_, p, su, sv); return;
    case Kind::Cone: ElSLib::D1(u, v, cone_, p, su, sv); return;
    case Kind::Sphere: ElSLib::D1(u, v, sphere_, p, su, sv); return;
    case Kind::Torus: ElSLib::D1(u, v, torus_, p, su, sv); return;
    case Kind::Other: break;
  }
  evaluator().D1(u, v, p, su, sv);
}

size_t SurfaceProjector::PointKeyHash::operator()(const PointKey& k) const {
  const auto bits = [](double d) {
    std::uint64_t b = 0;
    std::memcpy(&b, &d, sizeof b);
    return b;
  };
  std::uint64_t h = bits(k.x);
  for (const double d : {k.y, k.z}) h = (h ^ bits(d)) * 0x100000001b3ULL + (h >> 29);
  return static_cast<size_t>(h);
}

Vec2 SurfaceProjector::global(const gp_Pnt& p) const {
  return known_.local().answer({p.X(), p.Y(), p.Z()}, [&] { return global_uncached(p); });
}

Vec2 SurfaceProjector::global_uncached(const gp_Pnt& p) const {
  double u = 0.5 * (u0_ + u1_), v = 0.5 * (v0_ + v1_);
  bool found = false;
  try {
    auto& proj = per_thread_.local();
    if (!proj) {
      proj = std::make_unique<GeomAPI_ProjectPointOnSurf>();
      proj->Init(surface_, u0_, u1_, v0_, v1_);
    }
    proj->Perform(p);
    if (proj->IsDone() && proj->NbPoints() > 0) {
      proj->LowerDistanceParameters(u, v);
      found = true;
    }
  } catch (const Standard_Failure&) {
    per_thread_.local().reset();  // rebuilt on the next call
  }
  if (!found) {
    ShapeAnalysis_Surface sas(surface_);
    const gp_Pnt2d uv = sas.ValueOfUV(p, 1e-9);
    u = uv.X();
    v = uv.Y();
  }
  return Vec2(std::clamp(u, u0_, u1_), std::clamp(v, v0_, v1_));
}

void SurfaceProjector::build_samples() const {
  // Denser where the surface has more spans (B-spline knots), as OCCT's own
  // sampling; 25 x 25 at least, 65 x 65 at most. Stored in 5 x 5 tiles so a
  // query skips the tiles whose box is farther than its best sample so far.
  int nu = 24, nv = 24;
  const GeomAdaptor_Surface a(surface_);
  if (a.GetType() == GeomAbs_BSplineSurface) {
    nu = std::clamp(3 * a.NbUIntervals(GeomAbs_C2) * std::max(1, a.UDegree()), 24, 64);
    nv = std::clamp(3 * a.NbVIntervals(GeomAbs_C2) * std::max(1, a.VDegree()), 24, 64);
  }
  constexpr int kTile = 5;
  samples_.reserve(static_cast<size_t>((nu + 1) * (nv + 1)));
  for (int ti = 0; ti <= nu; ti += kTile) {
    for (int tj = 0; tj <= nv; tj += kTile) {
      Tile t{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}, samples_.size(), 0};
      for (int i = ti; i < std::min(ti + kTile, nu + 1); ++i) {
        for (int j = tj; j < std::min(tj + kTile, nv + 1); ++j) {
          const double u = u0_ + (u1_ - u0_) * i / nu, v = v0_ + (v1_ - v0_) * j / nv;
          const gp_Pnt q = surface_->Value(u, v);
          samples_.push_back({q.X(), q.Y(), q.Z(), u, v});
          const double c[3] = {q.X(), q.Y(), q.Z()};
          for (int k = 0; k < 3; ++k) {
            t.lo[k] = std::min(t.lo[k], c[k]);
            t.hi[k] = std::max(t.hi[k], c[k]);
          }
        }
      }
      t.end = samples_.size();
      tiles_.push_back(t);
    }
  }
}

std::optional<Vec2> SurfaceProjector::seeded(const gp_Pnt& p) const {
  if (kind_ != Kind::Other) return std::nullopt;
  std::call_once(samples_once_, [this] { build_samples(); });
  const double c[3] = {p.X(), p.Y(), p.Z()};
  const Sample* best = nullptr;
  double best_d2 = std::numeric_limits<double>::max();
  for (const Tile& t : tiles_) {
    double box_d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = c[k] < t.lo[k] ? t.lo[k] - c[k] : (c[k] > t.hi[k] ? c[k] - t.hi[k] : 0.0);
      box_d2 += d * d;
    }
    if (box_d2 >= best_d2) continue;
    for (size_t i = t.first; i < t.end; ++i) {
      const Sample& s = samples_[i];
      const double dx = s.x - c[0], dy = s.y - c[1], dz = s.z - c[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if (d2 < best_d2) {
        best_d2 = d2;
        best = &s;
      }
    }
  }
  if (!best) return std::nullopt;
  auto uv = newton(p, Vec2(best->u, best->v));
  if (!uv) return std::nullopt;
  // A descent that ended farther than its start found no better point.
  if (surface_->Value(uv->x(), uv->y()).SquareDistance(p) > best_d2 * (1 + 1e-12)) {
    return std::nullopt;
  }
  return uv;
}

Vec2 SurfaceProjector::closest(const gp_Pnt& p) const {
  std::optional<Vec2> outside;
  if (auto uv = closed_form(p, &outside)) return *uv;
  if (auto uv = seeded(p)) return *uv;
  const Vec2 g = global(p);
  if (outside && surface_->Value(outside->x(), outside->y()).SquareDistance(p) <
                     surface_->Value(g.x(), g.y()).SquareDistance(p))
    return *outside;
  return g;
}

}  // namespace cooperage::occ::detail
