#include "framework/core/error.h"

namespace cooperage {

const char* to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::InvalidInput: return "invalid input";
    case ErrorCode::FileNotFound: return "file not found";
    case ErrorCode::ParseError: return "parse error";
    case ErrorCode::GeometryError: return "geometry error";
    case ErrorCode::NotSupported: return "not supported yet";
    case ErrorCode::NotApplicable: return "not applicable";
    case ErrorCode::Infeasible: return "infeasible";
    case ErrorCode::MeshingFailed: return "meshing failed";
    case ErrorCode::Internal: return "internal error";
  }
  return "error";
}

std::string EntityRef::name() const {
  static const char* const kNames[] = {"vertex", "curve", "surface", "volume"};
  if (dim < 0 || dim > 3) return {};
  return std::string(kNames[dim]) + " " + std::to_string(id);
}

namespace {
std::string full_message(const EntityRef& entity, const std::string& message) {
  const std::string who = entity.name();
  return who.empty() ? message : who + ": " + message;
}
}  // namespace

MeshingError::MeshingError(ErrorCode code, EntityRef entity, const std::string& message)
    : std::runtime_error(full_message(entity, message)),
      code_(code),
      entity_(entity),
      message_(message) {}

}  // namespace cooperage
