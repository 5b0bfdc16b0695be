// SurfaceProjector: parameters of the point of an OCCT surface closest to a
// given point, within a face's parameter box. Three ways, cheapest first:
//  * closed form on elementary surfaces (plane, cylinder, cone, sphere,
//    torus; ElSLib), exact and global;
//  * a local Newton step on the squared distance from a parameter hint
//    (newton(); project_near in evaluators.h), or, without a hint, from the
//    nearest point of a uv sample grid built once per face (seeded());
//  * OCCT's global projector (GeomAPI_ProjectPointOnSurf), initialised once
//    per face and thread (its sampling grid is the expensive part: building
//    one per call cost 234-473 us a point on B-spline faces, issue 20) and
//    reused.
// Every result is a function of the query alone (never of the previous
// query), so meshes do not depend on the thread count.
// Internal to framework/geometry/occ (names OCCT types).
#pragma once

#include "framework/geometry/occ/shape_memo.h"
#include "framework/geometry/types.h"

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>
#include <gp_Vec.hxx>

#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace cooperage::occ::detail {

class SurfaceProjector {
 public:
  /// `surface` is immutable and shared; (u0..u1) x (v0..v1) the face's box.
  SurfaceProjector(const Handle(Geom_Surface) & surface, double u0, double u1, double v0,
                   double v1);

  /// Parameters of the closest point to p in the box: the closed form when
  /// the surface is elementary and its answer lies in the box, else the
  /// global projector (a clamped ShapeAnalysis inversion if that fails), or
  /// on an elementary surface the box point nearest its foot when closer.
  geom::Vec2 closest(const gp_Pnt& p) const;

  /// Exact parameters on an elementary surface, shifted into the box by
  /// whole periods; nullopt for other surfaces or when outside the box.
  /// `outside`, when given, receives the box point nearest the foot when the
  /// foot lies outside the face's box (a candidate for the closest point).
  std::optional<geom::Vec2> closed_form(const gp_Pnt& p,
                                        std::optional<geom::Vec2>* outside = nullptr) const;

  /// Local minimum of |S(u,v) - p| reached by Newton iterations from `hint`
  /// (clamped into the box). nullopt when the iteration does not converge,
  /// ends on the box boundary or at a point that is not a local minimum:
  /// the caller then falls back to closest().
  std::optional<geom::Vec2> newton(const gp_Pnt& p, const geom::Vec2& hint) const;

  /// Newton from the nearest sample of a grid over the box (built on first
  /// use), accepted only when it ends no farther than that sample; nullopt
  /// otherwise (and for elementary surfaces, which have closed forms).
  std::optional<geom::Vec2> seeded(const gp_Pnt& p) const;

  /// Point and first derivatives at (u, v), through this thread's adaptor
  /// (see evaluator()).
  void d1(double u, double v, gp_Pnt& p, gp_Vec& su, gp_Vec& sv) const;

 private:
  enum class Kind { Plane, Cylinder, Cone, Sphere, Torus, Other };

  geom::Vec2 global(const gp_Pnt& p) const;
  geom::Vec2 global_uncached(const gp_Pnt& p) const;
  /// This thread's adaptor of the surface. On a B-spline it keeps the
  /// polynomial of the last span evaluated (BSplSLib_Cache), so a run of
  /// evaluations in one span costs a Horner scheme each instead of the
  /// poles' recursion (a degree-13 loft spent half its run there, issue 20).
  const GeomAdaptor_Surface& evaluator() const;
  bool in_box(geom::Vec2& uv) const;  // shifts periodic parameters; true when inside

  Handle(Geom_Surface) surface_;
  double u0_, u1_, v0_, v1_;
  double scale_;  // model size of the face (for tolerances)
  Kind kind_ = Kind::Other;
  // The elementary surface, taken once: an adaptor built for every
  // closed-form projection was most of its cost (a cylinder's smoothing).
  gp_Pln plane_;
  gp_Cylinder cylinder_;
  gp_Cone cone_;
  gp_Sphere sphere_;
  gp_Torus torus_;
  bool u_periodic_ = false, v_periodic_ = false;
  double u_period_ = 0.0, v_period_ = 0.0;
  mutable tbb::enumerable_thread_specific<std::unique_ptr<GeomAPI_ProjectPointOnSurf>> per_thread_;
  /// global()'s answers by the query's exact coordinates, per thread: the
  /// decomposition search builds the facts of every piece of every cut,
  /// and most of a piece's vertices and curves are its solid's, projected
  /// onto the same faces again (a tenth of occt_CrankArm's refusal).
  struct PointKey {
    double x, y, z;
    bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct PointKeyHash {
    size_t operator()(const PointKey& k) const;
  };
  /// At most 256 a face and thread (a few kB): a mesh asks few points
  /// twice, a search its vertices and curve points on every piece.
  mutable tbb::enumerable_thread_specific<QueryMemo<PointKey, geom::Vec2, 256, PointKeyHash>>
      known_;
  mutable tbb::enumerable_thread_specific<std::unique_ptr<GeomAdaptor_Surface>> adaptors_;
  struct Sample {
    double x, y, z, u, v;
  };
  struct Tile {  // a block of neighbouring samples and their bounding box
    double lo[3], hi[3];
    size_t first, end;  // range in samples_
  };
  mutable std::once_flag samples_once_;
  mutable std::vector<Sample> samples_;  // tile by tile
  mutable std::vector<Tile> tiles_;
  void build_samples() const;
};

}  // namespace cooperage::occ::detail
