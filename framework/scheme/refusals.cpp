#include "framework/scheme/refusals.h"

namespace cooperage::scheme {

std::string join_refusals(const std::vector<std::pair<std::string, std::string>>& by_scheme) {
  std::string out;
  for (auto it = by_scheme.rbegin(); it != by_scheme.rend(); ++it)
    out += (out.empty() ? "" : "; ") + it->first + ": " + it->second;
  return out;
}

}  // namespace cooperage::scheme
