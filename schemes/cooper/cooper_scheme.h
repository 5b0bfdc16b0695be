// The volume scheme "cooper" (Blacker 1996): one code path for one barrel
// (the one-to-one sweep, any number of holes) and many (bosses, blind
// holes, pockets, bores through shoulders, appendages on both ends, sides
// stacked along the sweep, a curved axis). plan_volume() classifies the
// volume once -- the plan is cached and carried from applicable() to
// constrain(), roles() and mesh() -- and sweep_volume() meshes it.
// Wedge and mixed mode (Blacker 1996, abstract: "a wedge/hexahedral element
// mix ... by simply allowing triangle and/or mixed triangle/quadrilateral
// cap meshes"): caps are meshed by "tri" (wedge) or map / submap /
// "quad_dominant" (mixed), imprinted pieces by the triangle or
// quad-dominant polygon mesher; the sweep makes wedges from triangles and
// hexes from quads (elements.h).
#pragma once

#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/registry.h"
#include "framework/scheme/scheme.h"
#include "schemes/cooper/elements.h"
#include "schemes/cooper/plan_volume.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>
#include <vector>

namespace cooperage::cooper {

struct CooperOptions {
  /// Journal hints per volume id (sources, targets, direction; binding).
  std::map<int, SweepHints> hints;
  /// Meshes cap stacks that have no cap meshed by a surface scheme (Blacker
  /// 1996, sec. 6.1); null: volumes that need it are not applicable. The
  /// registration code wraps pave's 2D core (pave::pave_2d) here.
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
  /// The plan's verdict: one barrel scores 0.5-0.9, several 0.3-0.45 (the
  /// selector ranks volume map, one barrel, then many). Never meshes.
  scheme::Applicability applicable(const scheme::VolumeView& view) const override;
  /// The plan's rows: every linking chain of a level the same count, at
  /// least one layer per barrel, even cap loops where pieces are paved.
  void constrain(const scheme::VolumeView& view, intervals::IntervalProblem& problem) const override;
  /// Sides -> "submap"; caps meshed beforehand -> their scheme; the rest ->
  /// scheme::kMeshedByVolume. Empty when not applicable.
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override;
  std::vector<int> takes_existing_mesh(const scheme::VolumeView& view) const override;
  /// sweep_volume() on the plan. Throws MeshingError naming the volume.
  scheme::EntityMesh mesh(const scheme::VolumeView& view, const scheme::MeshParams& params) const override;

  /// The plan of a volume (computed on first use, then cached per model,
  /// volume and options).
  std::shared_ptr<const VolumePlan> plan(const scheme::VolumeView& view) const;

  /// Sets (or, with all lists empty and no direction, clears) the hints of a volume.
  void set_hints(int volume_id, std::vector<int> sources, std::vector<int> targets,
                 std::optional<geom::Vec3> direction = std::nullopt, std::string where = {});
  const CooperOptions& options() const { return options_; }
  /// The element kind of a volume (Hex unless set in the options).
  Elements elements(int volume_id) const;
  /// Sets the 2D mesher of imprinted subcaps in hex mode (see CooperOptions).
  void set_polygon_mesher(std::shared_ptr<const scheme::PolygonMesher> mesher);

 private:
  /// The polygon mesher of the volume's element kind (null: none given).
  const scheme::PolygonMesher* polygon_mesher(int volume_id) const;

  const scheme::Registry* registry_;
  CooperOptions options_;
  /// Plans by (model, volume, fingerprint of its faces, options version).
  using Key = std::tuple<const geom::Model*, int, std::uint64_t, int>;
  mutable std::mutex mutex_;
  mutable std::map<Key, std::shared_ptr<const VolumePlan>> plans_;
  mutable std::vector<Key> order_;  ///< insertion order, for eviction
  int version_ = 0;
};

/// The scheme; register it after the volume map.
std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry, CooperOptions options = {});

}  // namespace cooperage::cooper
