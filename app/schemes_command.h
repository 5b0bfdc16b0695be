// `cooperage schemes`: every registered scheme (built in and from plug-ins)
// with its dimension, where it came from and the roles it serves.
#pragma once

#include "framework/scheme/registry.h"

#include <ostream>

namespace cooperage::app {

/// One line per scheme, surfaces first, in registration order:
/// "surface  pave  built in  serves: quad cap".
void write_schemes_text(const scheme::Registry& registry, std::ostream& out);

/// The same as a JSON array of {name, dim (2 or 3), origin, serves}.
void write_schemes_json(const scheme::Registry& registry, std::ostream& out);

}  // namespace cooperage::app
