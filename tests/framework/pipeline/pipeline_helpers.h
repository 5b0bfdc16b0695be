// The registry and settings the pipeline tests mesh CAD models with.
#pragma once

#include "framework/scheme/registry.h"
#include "schemes/builtin_schemes.h"
#include "support/sized_settings.h"

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

}  // namespace cooperage::testing
