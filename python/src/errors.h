// Cooperage's MeshingError as Python exceptions: cooperage.InputError for
// what the command line reports with exit code 2 (bad input, no applicable
// scheme, infeasible intervals), cooperage.MeshingError for a scheme failing
// on an entity it accepted and internal errors; both derive from
// cooperage.Error and carry the same one-line message as the command line.
#pragma once

#include <pybind11/pybind11.h>

namespace cooperage::python {

/// Adds Error, InputError and MeshingError to `m` and translates
/// cooperage::MeshingError into them.
void register_errors(pybind11::module_& m);

}  // namespace cooperage::python
