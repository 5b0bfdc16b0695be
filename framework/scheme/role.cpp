#include "framework/scheme/role.h"

#include <utility>

namespace cooperage::scheme {

std::string to_string(Role roles) {
  static const std::pair<Role, const char*> kNames[] = {{Role::QuadCap, "quad cap"},
                                                        {Role::TriCap, "tri cap"},
                                                        {Role::MixedCap, "mixed cap"},
                                                        {Role::SweepSide, "sweep side"},
                                                        {Role::MappedFace, "mapped face"}};
  std::string out;
  for (const auto& [role, name] : kNames) {
    if (serves(roles, role)) out += (out.empty() ? "" : ", ") + std::string(name);
  }
  return out.empty() ? "none" : out;
}

}  // namespace cooperage::scheme
