// The volume scheme "cooper" (Blacker 1996): one code path for one barrel
// (the one-to-one sweep, any number of holes) and many (bosses, blind
// holes, pockets, bores through shoulders, appendages on both ends, sides
// stacked along the sweep, a curved axis). applicable() classifies the
// volume once with plan_volume() and returns the plan (CooperPlan, a
// scheme::PlanData); the selector keeps it and hands it back through the
// view to constrain(), roles(), takes_existing_mesh() and mesh(), and
// sweep_volume() meshes it. The scheme keeps no per-job state: a volume's
// sweep hints and element kind come from the view's scheme::Settings.
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

#include <memory>

namespace cooperage::cooper {

/// What an installation gives cooper once, at registration (the same for
/// every job).
struct CooperOptions {
  /// Meshes cap stacks that have no cap meshed by a surface scheme (Blacker
  /// 1996, sec. 6.1); null: volumes that need it are not applicable. The
  /// registration code wraps pave's 2D core (pave::pave_2d) here.
  std::shared_ptr<const scheme::PolygonMesher> polygon_mesher;
  /// The same for wedge mode (triangles; the registration code wraps
  /// framework/mesh2d) and mixed mode (quad-dominant; pave's 2D core with
  /// the quads below kMixedMinQuadQuality split, framework/mesh/split_poor_quads.h).
  std::shared_ptr<const scheme::PolygonMesher> triangle_mesher;
  std::shared_ptr<const scheme::PolygonMesher> quad_dominant_mesher;
};

/// Cooper's plan of one volume for one job, as applicable() returns it.
struct CooperPlan final : scheme::PlanData {
  VolumePlan plan;
  std::optional<std::array<double, 3>> straight_sweep() const override {
    if (!plan.ok || !plan.down) return std::nullopt;
    return std::array<double, 3>{plan.down->x(), plan.down->y(), plan.down->z()};
  }
};

/// The element kind a job asks of a volume (Settings::elements()).
Elements elements_of(const scheme::Settings& settings, int volume_id);
/// The journal's sweep hints of a volume (sources, targets, direction, with
/// its line); empty when it has none.
SweepHints hints_of(const scheme::Settings& settings, int volume_id);

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
  /// Returns the plan (CooperPlan), ok or not.
  scheme::Applicability applicable(const scheme::VolumeView& view) const override;
  /// The plan's rows: every linking chain of a level the same count, at
  /// least one layer per barrel, even cap loops where pieces are paved.
  void constrain(const scheme::VolumeView& view,
                 intervals::IntervalProblem& problem) const override;
  /// Sides -> "submap"; caps meshed beforehand -> their scheme; the rest ->
  /// scheme::kMeshedByVolume. Empty when not applicable.
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override;
  std::vector<int> takes_existing_mesh(const scheme::VolumeView& view) const override;
  int sweep_source(const scheme::VolumeView& view) const override;
  /// The side corners the lattice typed to agree with their neighbours.
  std::vector<io::VertexTypeSetting> vertex_types(const scheme::VolumeView& view) const override;
  void space_curves(const scheme::VolumeView& view, const std::map<int, int>& counts,
                    std::map<int, mesh::SizeFunction>& sizes) const override;
  /// sweep_volume() on the plan. Throws MeshingError naming the volume.
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override;

  /// The plan view.plan carries (this scheme's applicable() for the same
  /// volume), else one computed now from the view's model and settings.
  std::shared_ptr<const CooperPlan> plan(const scheme::VolumeView& view) const;
  const CooperOptions& options() const { return options_; }

 private:
  /// The polygon mesher of an element kind (null: none given).
  const scheme::PolygonMesher* polygon_mesher(Elements elements) const;

  const scheme::Registry* registry_;
  CooperOptions options_;
};

/// The scheme; register it after the volume map.
std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry,
                                                  CooperOptions options = {});

}  // namespace cooperage::cooper
