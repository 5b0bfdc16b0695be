// The string options of cooperage.mesh() and cooperage.plan() read into
// their settings; a value that is none of the choices is an InputError
// naming the function and the argument, not a silent default.
#pragma once

#include <string>
#include <variant>

#include "framework/io/element_size.h"
#include "framework/io/job.h"

namespace cooperage::python {

/// "hex", "wedge" or "mixed".
io::ElementKind element_kind(const std::string& name, const std::string& function);

/// A length (a positive number) or "D/N" (the bounding-box diagonal over N).
io::ElementSize element_size(const std::variant<double, std::string>& size,
                             const std::string& function);

/// "auto" or "off".
io::Decompose decompose_mode(const std::string& name, const std::string& function);

}  // namespace cooperage::python
