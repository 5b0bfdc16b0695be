// Total surface meshing (issue 16, item 1): a surface scheme that, when the
// surface mesh is the product (Settings::allow_fallback, `--dim 2`), never
// gives up on a valid face. It tries, in order, and keeps the first mesh
// whose every element reaches `min_quality` (scaled Jacobian against the
// surface normal, measured in 3D):
//   1. its primary scheme (map, submap or pave, as the selector chose);
//   2. the all-quad fallback (pave), if the primary is not pave;
//   3. quad-dominant: the best quad mesh of 1-2 with its quads below
//      min_quality split into triangles (framework/mesh/split_poor_quads.h);
//   4. on a strip (one loop between two tips, thinner than its elements: a
//      thread's flank), one row of quads with a triangle at each tip
//      (framework/mesh/strip_elements.h), where triangles would be needles;
//   5. triangles (the tri scheme), the last resort.
// A face with a corner sharper than asin(min_quality) cannot reach it: no
// element at a corner of angle a exceeds sin(a). There the bar is
// reachable_floor(): a mesh that reaches what the corner allows is kept as
// it is, with a warning, rather than traded for triangles.
// When none reaches the bar, the valid mesh (nothing inverted) with the
// best worst element is kept. Every step past the primary adds a sentence to
// EntityMesh::warnings saying what was given up and why; nothing inverted is
// ever returned (no valid mesh at all: the primary's error, with the
// fallbacks' reasons). Without allow_fallback (a volume scheme imposed the
// surface's scheme, e.g. cooper's submapped sides) it is the primary alone,
// except that with Settings::allow_quad_fallback (in 3D, a surface every
// volume takes as it finds it: cooper's uncut source caps) a failing
// primary gives way to step 2, the all-quad fallback.
// applicable() and constrain() are the primary's: every quad scheme's
// constraints make the boundary interval total even, which pave and the
// quad-dominant split need, and tri takes any count.
#pragma once

#include "framework/scheme/scheme.h"

#include <memory>

namespace cooperage::quad_dominant {

/// Corners sharper than this [degrees] count as this sharp: at a cusp (0
/// degrees between tangents) the chords still open an angle.
inline constexpr double kSharpestCornerCounted = 3.0;

/// The worst element a chain accepts on a face whose sharpest corner is
/// `sharpest_degrees`: min(min_quality, 0.95 sin(max(sharpest, 3 degrees))).
double reachable_floor(double min_quality, double sharpest_degrees);

class FallbackChain final : public scheme::SurfaceScheme {
 public:
  /// \param[in] primary      the scheme whose name, a-priori test and constraints this is
  /// \param[in] quads        the all-quad fallback (nullptr when primary is it)
  /// \param[in] triangles    the last resort
  /// \param[in] min_quality  the scaled Jacobian every element should reach
  FallbackChain(std::unique_ptr<scheme::SurfaceScheme> primary,
                std::unique_ptr<scheme::SurfaceScheme> quads,
                std::unique_ptr<scheme::SurfaceScheme> triangles, double min_quality = 0.2);
  std::string_view name() const override { return primary_->name(); }
  /// The primary's roles: the chain stands for it in the registry.
  scheme::Role serves() const override { return primary_->serves(); }
  scheme::Applicability applicable(const scheme::SurfaceView& view) const override {
    return primary_->applicable(view);
  }
  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override {
    primary_->constrain(view, problem);
  }
  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& params) const override;

 private:
  /// Settings::allow_quad_fallback: the primary, or when it fails, the
  /// all-quad fallback's valid mesh with a warning; else the primary's error.
  scheme::EntityMesh primary_or_quads(const scheme::SurfaceView& view,
                                      const scheme::Settings& params) const;

  std::unique_ptr<scheme::SurfaceScheme> primary_;
  std::unique_ptr<scheme::SurfaceScheme> quads_;
  std::unique_ptr<scheme::SurfaceScheme> triangles_;
  double min_quality_;
};

}  // namespace cooperage::quad_dominant
