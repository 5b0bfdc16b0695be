#include "framework/scheme/registry.h"

#include "framework/core/error.h"

namespace cooperage::scheme {

void Registry::add(std::unique_ptr<SurfaceScheme> scheme) {
  if (surface_scheme(scheme->name())) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "surface scheme \"" + std::string(scheme->name()) + "\" registered twice");
  }
  surface_.push_back(std::move(scheme));
}

void Registry::add(std::unique_ptr<VolumeScheme> scheme) {
  if (volume_scheme(scheme->name())) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "volume scheme \"" + std::string(scheme->name()) + "\" registered twice");
  }
  volume_.push_back(std::move(scheme));
}

const SurfaceScheme* Registry::surface_scheme(std::string_view name) const {
  for (const auto& s : surface_) {
    if (s->name() == name) return s.get();
  }
  return nullptr;
}

const VolumeScheme* Registry::volume_scheme(std::string_view name) const {
  for (const auto& s : volume_) {
    if (s->name() == name) return s.get();
  }
  return nullptr;
}

std::vector<const SurfaceScheme*> Registry::surface_schemes() const {
  std::vector<const SurfaceScheme*> r;
  for (const auto& s : surface_) r.push_back(s.get());
  return r;
}

std::vector<const VolumeScheme*> Registry::volume_schemes() const {
  std::vector<const VolumeScheme*> r;
  for (const auto& s : volume_) r.push_back(s.get());
  return r;
}

}  // namespace cooperage::scheme
