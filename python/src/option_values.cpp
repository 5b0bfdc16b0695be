#include "option_values.h"

#include <cmath>

#include "framework/core/error.h"

namespace cooperage::python {

io::ElementKind element_kind(const std::string& name, const std::string& function) {
  if (name == "hex") return io::ElementKind::Hex;
  if (name == "wedge") return io::ElementKind::Wedge;
  if (name == "mixed") return io::ElementKind::Mixed;
  throw MeshingError(ErrorCode::InvalidInput, function +
                                                  ": elements must be \"hex\", \"wedge\" or "
                                                  "\"mixed\", got \"" +
                                                  name + "\"");
}

io::ElementSize element_size(const std::variant<double, std::string>& size,
                             const std::string& function) {
  if (const double* length = std::get_if<double>(&size)) {
    if (*length > 0 && std::isfinite(*length)) return {*length, false};
    throw MeshingError(
        ErrorCode::InvalidInput,
        function + ": the element size must be positive, got " + std::to_string(*length));
  }
  const std::string& text = std::get<std::string>(size);
  if (const auto parsed = io::parse_element_size(text)) return *parsed;
  throw MeshingError(ErrorCode::InvalidInput,
                     function +
                         ": size must be a positive number or \"D/N\" (the model's "
                         "bounding-box diagonal over N), got \"" +
                         text.substr(0, 40) + "\"");
}

io::Decompose decompose_mode(const std::string& name, const std::string& function) {
  if (name == "auto") return io::Decompose::Auto;
  if (name == "off") return io::Decompose::Off;
  throw MeshingError(ErrorCode::InvalidInput,
                     function + ": decompose must be \"auto\" or \"off\", got \"" + name + "\"");
}

}  // namespace cooperage::python
