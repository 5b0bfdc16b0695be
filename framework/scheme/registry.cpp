#include "framework/scheme/registry.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cctype>

namespace cooperage::scheme {
namespace {

const char* dimension_word(int dim) { return dim == 3 ? "volume" : "surface"; }

template <class Entries>
const typename Entries::value_type* find_entry(const Entries& entries, std::string_view name) {
  for (const auto& e : entries) {
    if (e.scheme->name() == name) return &e;
  }
  return nullptr;
}

}  // namespace

void Registry::check_name(int dim, std::string_view name) const {
  const std::string what =
      std::string(dimension_word(dim)) + " scheme \"" + std::string(name) + "\"";
  const bool valid_chars = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (name.empty() || name == "auto" || !valid_chars) {
    throw MeshingError(ErrorCode::InvalidInput,
                       what +
                           " has an invalid name: a name is made of letters, digits, '_', '-' "
                           "and '.', and is not \"auto\"");
  }
  const std::string taken = origin(dim, name);
  if (!taken.empty()) {
    throw MeshingError(ErrorCode::InvalidInput,
                       what + " from " + origin_ + " is already registered (" + taken + ")");
  }
}

void Registry::add(std::unique_ptr<SurfaceScheme> scheme) {
  check_name(2, scheme->name());
  surface_.push_back({std::move(scheme), origin_});
}

void Registry::add(std::unique_ptr<VolumeScheme> scheme) {
  check_name(3, scheme->name());
  volume_.push_back({std::move(scheme), origin_});
}

const SurfaceScheme* Registry::surface_scheme(std::string_view name) const {
  const auto* e = find_entry(surface_, name);
  return e ? e->scheme.get() : nullptr;
}

const VolumeScheme* Registry::volume_scheme(std::string_view name) const {
  const auto* e = find_entry(volume_, name);
  return e ? e->scheme.get() : nullptr;
}

std::vector<const SurfaceScheme*> Registry::surface_schemes() const {
  std::vector<const SurfaceScheme*> r;
  for (const auto& e : surface_) r.push_back(e.scheme.get());
  return r;
}

std::vector<const SurfaceScheme*> Registry::surface_schemes(Role role) const {
  std::vector<const SurfaceScheme*> r;
  for (const auto& e : surface_) {
    if (serves(e.scheme->serves(), role)) r.push_back(e.scheme.get());
  }
  return r;
}

std::vector<const VolumeScheme*> Registry::volume_schemes() const {
  std::vector<const VolumeScheme*> r;
  for (const auto& e : volume_) r.push_back(e.scheme.get());
  return r;
}

std::vector<std::string> Registry::names(int dim) const {
  std::vector<std::string> r;
  if (dim == 3) {
    for (const auto& e : volume_) r.emplace_back(e.scheme->name());
  } else {
    for (const auto& e : surface_) r.emplace_back(e.scheme->name());
  }
  return r;
}

std::string Registry::origin(int dim, std::string_view name) const {
  if (dim == 3) {
    const auto* e = find_entry(volume_, name);
    return e ? e->origin : std::string();
  }
  const auto* e = find_entry(surface_, name);
  return e ? e->origin : std::string();
}

Registry::OriginScope::OriginScope(Registry& registry, std::string origin)
    : registry_(registry), previous_(registry.origin_) {
  registry_.libraries_.insert(origin);
  registry_.origin_ = std::move(origin);
}

Registry::OriginScope::~OriginScope() { registry_.origin_ = std::move(previous_); }

RoleChoice best_surface_scheme(const Registry& registry, Role role, const SurfaceView& view) {
  RoleChoice best;
  for (const SurfaceScheme* s : registry.surface_schemes(role)) {
    Applicability a = s->applicable(view);
    if (!a.ok) {
      best.reasons += (best.reasons.empty() ? "" : "; ") + std::string(s->name()) + ": " + a.why;
    } else if (!best.scheme || a.score > best.applicability.score) {
      best.scheme = s;
      best.applicability = std::move(a);
    }
  }
  if (registry.surface_schemes(role).empty()) {
    best.reasons = std::string("no registered surface scheme serves ") + to_string(role);
  }
  return best;
}

}  // namespace cooperage::scheme
