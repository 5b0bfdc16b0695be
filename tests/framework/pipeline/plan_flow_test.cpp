// How plans and settings reach a scheme (docs/design.md, "Plans and
// settings"): the plan applicable() returns is the one constrain(), roles(),
// takes_existing_mesh() and mesh() get back, computed once per entity and
// run; the settings are the run's. A scheme that wraps the volume map
// records every call, as a plug-in could.
#include "support/hex_mesh_check.h"

#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "schemes/map/volume_map.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace cooperage::pipeline {
namespace {

// The wrapper's plan: a serial number, and the volume map's own plan.
struct CountedPlan final : scheme::PlanData {
  int volume = 0;
  int serial = 0;
  std::shared_ptr<const scheme::PlanData> inner;
};

// The volume map under another name, recording which plan each call got.
class Counted final : public scheme::VolumeScheme {
 public:
  struct Call {
    std::string what;  ///< "constrain", "roles", "takes", "mesh"
    int volume = 0;
    const scheme::PlanData* plan = nullptr;
    const scheme::Settings* settings = nullptr;
  };

  std::string_view name() const override { return "counted"; }

  scheme::Applicability applicable(const scheme::VolumeView& view) const override {
    auto p = std::make_shared<CountedPlan>();
    p->volume = view.volume_id;
    scheme::Applicability a = inner_->applicable(view);
    p->inner = a.plan;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      p->serial = static_cast<int>(made_.size());
      made_.push_back(p.get());
      settings_seen_.push_back(view.job);
    }
    a.plan = std::move(p);
    return a;
  }
  void constrain(const scheme::VolumeView& view,
                 intervals::IntervalProblem& problem) const override {
    inner_->constrain(inner_view(view, "constrain"), problem);
  }
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override {
    return inner_->roles(inner_view(view, "roles"));
  }
  std::vector<int> takes_existing_mesh(const scheme::VolumeView& view) const override {
    return inner_->takes_existing_mesh(inner_view(view, "takes"));
  }
  scheme::EntityMesh mesh(const scheme::VolumeView& view,
                          const scheme::Settings& settings) const override {
    return inner_->mesh(inner_view(view, "mesh"), settings);
  }

  std::vector<const scheme::PlanData*> made() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return made_;
  }
  std::vector<const scheme::Settings*> settings_seen() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return settings_seen_;
  }
  std::vector<Call> calls() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return calls_;
  }

 private:
  scheme::VolumeView inner_view(const scheme::VolumeView& view, const char* what) const {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      calls_.push_back({what, view.volume_id, view.plan, view.job});
    }
    scheme::VolumeView inner = view;
    const auto* p = scheme::carried_plan<CountedPlan>(view);
    inner.plan = p ? p->inner.get() : nullptr;
    return inner;
  }

  std::unique_ptr<scheme::VolumeScheme> inner_ = map::make_volume_map();
  // Test instrumentation only: a real scheme keeps nothing per job.
  mutable std::mutex mutex_;
  mutable std::vector<const scheme::PlanData*> made_;
  mutable std::vector<const scheme::Settings*> settings_seen_;
  mutable std::vector<Call> calls_;
};

io::MeshSettings pinned_to_counted(double size, int volumes) {
  io::MeshSettings s;
  s.size = size;
  for (int v = 1; v <= volumes; ++v) {
    io::VolumeSetting setting;
    setting.id = v;
    setting.scheme = "counted";
    s.volumes.push_back(setting);
  }
  return s;
}

TEST(PlanFlow, ThePlanApplicableReturnsIsTheOneEveryLaterCallGets) {
  occ::Workbench wb;
  wb.brick("a", {0, 0, 0}, {2, 1, 1});
  wb.brick("b", {2, 0, 0}, {1, 1, 1});  // shares a face with a: two volumes
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 2u);
  scheme::Registry registry;
  register_builtin_schemes(registry);
  auto owned = std::make_unique<Counted>();
  const Counted* counted = owned.get();
  registry.add(std::move(owned));

  const MeshResult r =
      mesh_model(model, pinned_to_counted(0.25, 2), registry, selector::mesh_options());
  // One analysis per volume and run: the selector's.
  const std::vector<const scheme::PlanData*> made = counted->made();
  ASSERT_EQ(made.size(), 2u);
  for (const scheme::Settings* s : counted->settings_seen()) EXPECT_NE(s, nullptr);
  // The pipeline's plan keeps them, one per volume.
  for (int v : {1, 2}) {
    const auto* kept = dynamic_cast<const CountedPlan*>(r.plan.volumes.at(v).data.get());
    ASSERT_NE(kept, nullptr) << "volume " << v;
    EXPECT_EQ(kept->volume, v);
  }
  // Every later call got its volume's plan back, and mesh() ran once each.
  std::map<std::string, int> count;
  for (const Counted::Call& c : counted->calls()) {
    ++count[c.what];
    EXPECT_EQ(c.plan, r.plan.volumes.at(c.volume).data.get())
        << c.what << " of volume " << c.volume;
    EXPECT_NE(c.settings, nullptr) << c.what;
  }
  EXPECT_EQ(count["mesh"], 2);
  EXPECT_GE(count["constrain"], 2);
  EXPECT_EQ(count["roles"], 2);
  // ... and what it meshed is the two blocks.
  const cooperage::testing::HexMeshSummary m =
      cooperage::testing::check_hex_mesh(model, r.mesh);  // conformal, none inverted
  EXPECT_NEAR(m.volume, 3.0, 1e-9);
  EXPECT_EQ(r.mesh.hex_count(), static_cast<size_t>(8 * 4 * 4 + 4 * 4 * 4));
}

TEST(PlanFlow, ASchemeWithoutItsPlanComputesItAgain) {
  occ::Workbench wb;
  wb.brick("a", {0, 0, 0}, {1, 1, 1});
  const geom::Model model = wb.build_model();
  scheme::Registry registry;
  register_builtin_schemes(registry);
  const scheme::VolumeScheme* cooper = registry.volume_scheme("cooper");
  // Another scheme's plan in the view is not taken for cooper's.
  const auto foreign = std::make_shared<CountedPlan>();
  const scheme::VolumeView with_foreign{model, 1, nullptr, nullptr, foreign.get()};
  const scheme::Applicability a = cooper->applicable(with_foreign);
  ASSERT_TRUE(a.ok) << a.why;
  ASSERT_NE(a.plan, nullptr);
  EXPECT_NE(a.plan.get(), foreign.get());
  // Cooper's own plan is handed back unchanged: the same roles either way.
  const scheme::VolumeView carried{model, 1, nullptr, nullptr, a.plan.get()};
  EXPECT_EQ(cooper->roles(carried), cooper->roles(scheme::VolumeView{model, 1, nullptr}));
  // A second applicable() is a second analysis (nothing is cached in the scheme).
  EXPECT_NE(cooper->applicable(scheme::VolumeView{model, 1, nullptr}).plan.get(), a.plan.get());
}

}  // namespace
}  // namespace cooperage::pipeline
