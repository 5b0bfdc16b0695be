#include "option_values.h"

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

io::Decompose decompose_mode(const std::string& name, const std::string& function) {
  if (name == "auto") return io::Decompose::Auto;
  if (name == "off") return io::Decompose::Off;
  throw MeshingError(ErrorCode::InvalidInput,
                     function + ": decompose must be \"auto\" or \"off\", got \"" + name + "\"");
}

}  // namespace cooperage::python
