// A test volume scheme that plans as the volume map does (applicable,
// constrain, roles) and meshes as the test says: a scheme that accepts a
// volume and then fails on it, as cooper does on some parts.
#pragma once

#include "framework/scheme/scheme.h"

namespace cooperage::pipeline::testing {

class PlansLikeMap : public scheme::VolumeScheme {
 public:
  explicit PlansLikeMap(const scheme::VolumeScheme& map) : map_(map) {}
  scheme::Applicability applicable(const scheme::VolumeView& view) const override {
    return map_.applicable(view);
  }
  void constrain(const scheme::VolumeView& view,
                 intervals::IntervalProblem& problem) const override {
    map_.constrain(view, problem);
  }
  scheme::SurfaceRoles roles(const scheme::VolumeView& view) const override {
    return map_.roles(view);
  }

 protected:
  const scheme::VolumeScheme& map_;
};

}  // namespace cooperage::pipeline::testing
