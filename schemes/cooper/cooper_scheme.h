// The volume scheme "cooper" (Blacker 1996). Part I: every single-barrel
// volume (the one-to-one sweep, any number of holes) meshes automatically
// from an element size. Part II: many-to-one volumes (several source caps,
// bosses, shoulders and through holes along one axis; classify_barrels.h,
// sweep_many_to_one.h). Sides are submapped, the source caps are meshed by
// map / submap / pave, the target cap is meshed here (kMeshedByVolume).
// Wedge and mixed mode (Blacker 1996, abstract: "a wedge/hexahedral element
// mix ... by simply allowing triangle and/or mixed triangle/quadrilateral
// cap meshes"): every cap stack is meshed by "tri" (wedge) or map / submap /
// "quad_dominant" (mixed), imprinted pieces of caps by the triangle or
// quad-dominant polygon mesher; the sweep makes wedges from triangles and
// hexes from quads, one-to-one and many-to-one (elements.h).
#pragma once

#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/registry.h"
#include "framework/scheme/scheme.h"
#include "schemes/cooper/classify_barrels.h"
#include "schemes/cooper/classify_faces.h"
#include "schemes/cooper/elements.h"

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace cooperage::cooper {

struct CooperOptions {
  /// Journal hints per volume id (sources, targets, direction).
  std::map<int, SweepHints> hints;
  /// Meshes imprinted subcaps that are no model surface (Blacker 1996,
  /// sec. 6.1); null: barrels with subcaps on both ends are not applicable.
  /// The registration code wraps pave's 2D core (pave::pave_2d) here.
  std::shared_ptr<const scheme::PolygonMesher> polygon_mesher;
  /// The same for wedge mode (triangles; the registration code wraps
  /// framework/mesh2d) and mixed mode (quad-dominant; pave's 2D core with
  /// the quads below kMixedMinQuadQuality split, framework/mesh/split_poor_quads.h).
  std::shared_ptr<const scheme::PolygonMesher> triangle_mesher;
  std::shared_ptr<const scheme::PolygonMesher> quad_dominant_mesher;
  /// Element kind per volume id (journal `elements=`); absent: Hex.
  std::map<int, Elements> elements;
};

class CooperScheme final : public scheme::VolumeScheme {
 public:
  /// Keeps `registry` (it must outlive the scheme) to ask the schemes that
  /// serve sweep sides and caps (scheme::Role) for their applicable().
  explicit CooperScheme(const scheme::Registry& registry, CooperOptions options = {})
      : registry_(&registry), options_(std::move(options)) {}

  std::string_view name() const override { return "cooper"; }
  bool makes_wedges() const override { return true; }
  /// classify_faces(): a one-barrel volume (two caps, submappable sides,
  /// convex end caps, a source cap scheme of the element kind), else
  /// classify_barrels() with the caps' schemes of the element kind. Never meshes.
  scheme::Applicability applicable(const scheme::VolumeView& view) const override;
  /// Per side: source-boundary sum == target-boundary sum; every linking
  /// chain of the volume the same count (Blacker 1996, sec. 3-4).
  void constrain(const scheme::VolumeView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Sides -> the sweep-side scheme (submap), source caps -> their scheme
  /// ("tri" in wedge mode, map/submap/"quad_dominant" in mixed mode), target
  /// -> scheme::kMeshedByVolume. Empty when not applicable.
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override;
  /// Barrel formation, projection, elements. Throws MeshingError
  /// (MeshingFailed) naming the volume: ribs that do not end on the target
  /// boundary (many-to-one, part II), or elements that stay inverted.
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::MeshParams& params) const override;

  /// Sets (or, with all lists empty and no direction, clears) the hints of a volume.
  void set_hints(int volume_id, std::vector<int> sources, std::vector<int> targets,
                 std::optional<geom::Vec3> direction = std::nullopt);
  const CooperOptions& options() const { return options_; }
  /// The element kind of a volume (Hex unless set in the options).
  Elements elements(int volume_id) const;
  /// Sets the 2D mesher of imprinted subcaps in hex mode (see CooperOptions).
  void set_polygon_mesher(std::shared_ptr<const scheme::PolygonMesher> mesher) {
    options_.polygon_mesher = std::move(mesher);
  }

 private:
  Classification classify(const scheme::VolumeView& view) const;
  ManyToOne classify_many(const scheme::VolumeView& view) const;
  /// The polygon mesher of the volume's element kind (null: none given).
  const scheme::PolygonMesher* polygon_mesher(int volume_id) const;
  void constrain_many(const scheme::VolumeView& view, intervals::IntervalProblem& problem) const;

  const scheme::Registry* registry_;
  CooperOptions options_;
};

/// The scheme; register it after the volume map.
std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry,
                                                  CooperOptions options = {});

}  // namespace cooperage::cooper
