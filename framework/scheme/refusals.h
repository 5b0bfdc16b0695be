// Every scheme's refusal of one entity, joined into one reason for a person.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cooperage::scheme {

/// "cooper: ...; map: ...": the refusals given in registry order, joined
/// with the last registered first. Schemes are registered from the most
/// particular (map: six faces) to the most general (cooper, pave); the
/// general one's reason tells most about the entity ("surface 39 cannot be a
/// side (it has 2 loops ...)" against "volume map needs 6 mappable surfaces,
/// volume has 58"), and an error clipped to a line shows the first. "" for
/// none.
std::string join_refusals(const std::vector<std::pair<std::string, std::string>>& by_scheme);

}  // namespace cooperage::scheme
