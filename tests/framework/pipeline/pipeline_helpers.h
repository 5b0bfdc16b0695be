// The registry and settings the pipeline tests mesh CAD models with.
#pragma once

#include "framework/io/job.h"
#include "framework/scheme/registry.h"
#include "schemes/builtin_schemes.h"

namespace cooperage::testing {

/// The built-in schemes, registered once for the whole test run.
inline const scheme::Registry& builtin_registry() {
  static const scheme::Registry& r = *[] {
    auto* registry = new scheme::Registry;  // lives for the whole test run
    register_builtin_schemes(*registry);
    return registry;
  }();
  return r;
}

/// An element size and no retry at a finer one: the scheme at this size.
inline io::MeshSettings sized_without_retries(double size) {
  io::MeshSettings s;
  s.size = size;
  s.finer_retries = 0;
  return s;
}

}  // namespace cooperage::testing
