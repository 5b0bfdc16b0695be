#include "schemes/cooper/cooper_scheme.h"

#include "framework/core/error.h"
#include "schemes/cooper/sweep_volume.h"

#include <cstring>

namespace cooperage::cooper {
namespace {

constexpr size_t kMaxCachedPlans = 256;

// FNV-1a over the bytes of a value.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  template <class T>
  void add(const T& v) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    for (unsigned char b : bytes) {
      h ^= b;
      h *= 1099511628211ull;
    }
  }
};

// What the plan of a volume depends on: its faces, their loops, measures
// and boxes (a model destroyed and another built at the same address with
// the same fingerprint would be the same volume).
std::uint64_t fingerprint(const geom::Model& model, int volume_id) {
  Hash h;
  for (const auto& shell : model.volume(volume_id).shells) {
    for (const auto& use : shell) {
      const geom::Surface& s = model.surface(use.surface);
      h.add(s.id);
      h.add(static_cast<int>(use.sense));
      h.add(s.area);
      h.add(s.box.min.x());
      h.add(s.box.min.y());
      h.add(s.box.min.z());
      h.add(s.box.max.x());
      h.add(s.box.max.y());
      h.add(s.box.max.z());
      h.add(s.geometry.get());
      h.add(s.volumes.size());
      for (const auto& loop : s.loops) {
        for (const auto& u : loop.uses) {
          h.add(u.curve);
          h.add(static_cast<int>(u.sense));
          h.add(model.curve(u.curve).length);
        }
        h.add(-1);
      }
    }
  }
  return h.h;
}

}  // namespace

Elements CooperScheme::elements(int volume_id) const {
  const auto it = options_.elements.find(volume_id);
  return it == options_.elements.end() ? Elements::Hex : it->second;
}

const scheme::PolygonMesher* CooperScheme::polygon_mesher(int volume_id) const {
  switch (elements(volume_id)) {
    case Elements::Wedge: return options_.triangle_mesher.get();
    case Elements::Mixed: return options_.quad_dominant_mesher.get();
    case Elements::Hex: break;
  }
  return options_.polygon_mesher.get();
}

std::shared_ptr<const VolumePlan> CooperScheme::plan(const scheme::VolumeView& view) const {
  const Key key{&view.model, view.volume_id, fingerprint(view.model, view.volume_id), version_};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = plans_.find(key);
    if (it != plans_.end()) return it->second;
  }
  PlanInputs in;
  const auto h = options_.hints.find(view.volume_id);
  if (h != options_.hints.end()) in.hints = h->second;
  in.elements = elements(view.volume_id);
  in.polygon_mesher = polygon_mesher(view.volume_id) != nullptr;
  auto p = std::make_shared<const VolumePlan>(plan_volume(view.model, view.volume_id, *registry_, in));
  std::lock_guard<std::mutex> lock(mutex_);
  const auto [it, added] = plans_.emplace(key, p);
  if (added) {
    order_.push_back(key);
    if (order_.size() > kMaxCachedPlans) {
      plans_.erase(order_.front());
      order_.erase(order_.begin());
    }
  }
  return it->second;
}

scheme::Applicability CooperScheme::applicable(const scheme::VolumeView& view) const {
  const auto p = plan(view);
  return p->ok ? scheme::Applicability::yes(p->score, p->why) : scheme::Applicability::no(p->why);
}

void CooperScheme::constrain(const scheme::VolumeView& view, intervals::IntervalProblem& problem) const {
  const auto p = plan(view);
  if (p->ok) add_rows(p->rows, problem);
}

scheme::SurfaceRoles CooperScheme::roles(const scheme::VolumeView& view) const {
  const auto p = plan(view);
  scheme::SurfaceRoles roles;
  if (!p->ok) return roles;
  for (int s : p->lattice.sides) roles[s] = "submap";
  for (const auto& [cap, upper] : p->order.upper) {
    const auto it = p->roles.scheme.find(cap);
    roles[cap] = it != p->roles.scheme.end() ? it->second : scheme::kMeshedByVolume;
  }
  return roles;
}

// cite: Blacker 1996, sec. 6.1 (a stack is meshed from "an existing
// mesh"): a cap meshed beforehand is swept as it is, whoever meshed it.
std::vector<int> CooperScheme::takes_existing_mesh(const scheme::VolumeView& view) const {
  const auto p = plan(view);
  std::vector<int> out;
  if (!p->ok) return out;
  for (const auto& [cap, scheme] : p->roles.scheme) out.push_back(cap);
  return out;
}

// cite: Blacker 1996, sec. 4-6 (barrels, subcaps, cap stacks, projection,
// elements); the one-barrel sweep is the same path with one barrel.
scheme::EntityMesh CooperScheme::mesh(const scheme::VolumeView& view, const scheme::MeshParams& /*params*/) const {
  const auto p = plan(view);
  if (!p->ok) {
    throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(view.volume_id), p->why);
  }
  return sweep_volume(view, *p, polygon_mesher(view.volume_id));
}

void CooperScheme::set_hints(int volume_id, std::vector<int> sources, std::vector<int> targets,
                             std::optional<geom::Vec3> direction, std::string where) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++version_;
  if (sources.empty() && targets.empty() && !direction) {
    options_.hints.erase(volume_id);
    return;
  }
  options_.hints[volume_id] = SweepHints{std::move(sources), std::move(targets), direction, std::move(where)};
}

void CooperScheme::set_polygon_mesher(std::shared_ptr<const scheme::PolygonMesher> mesher) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++version_;
  options_.polygon_mesher = std::move(mesher);
}

std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry, CooperOptions options) {
  return std::make_unique<CooperScheme>(registry, std::move(options));
}

}  // namespace cooperage::cooper
