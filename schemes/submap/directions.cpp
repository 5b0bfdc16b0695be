#include "schemes/submap/directions.h"

namespace cooperage::submap {

const char* direction_name(int d) {
  static const char* names[4] = {"+i", "+j", "-i", "-j"};
  return names[((d % 4) + 4) % 4];
}

std::array<int, 2> direction_step(int d) {
  switch (((d % 4) + 4) % 4) {
    case kPlusI: return {1, 0};
    case kPlusJ: return {0, 1};
    case kMinusI: return {-1, 0};
    default: return {0, -1};
  }
}

std::vector<int> use_directions(const std::vector<VertexType>& types, int start) {
  const size_t n = types.size();
  std::vector<int> dirs(n, 0);
  if (n == 0) return dirs;
  size_t first = 0;
  for (size_t k = 0; k < n; ++k) {
    if (types[k] == VertexType::End) {
      first = k;
      break;
    }
  }
  int d = ((start % 4) + 4) % 4;
  dirs[first] = d;
  for (size_t step = 1; step < n; ++step) {
    const size_t k = (first + step) % n;
    d = (((d + t_of(types[k])) % 4) + 4) % 4;
    dirs[k] = d;
  }
  return dirs;
}

std::array<std::map<int, int>, 2> loop_balance(const std::vector<DirectedUse>& uses) {
  std::array<std::map<int, int>, 2> axes;
  for (const auto& u : uses) {
    const int d = ((u.direction % 4) + 4) % 4;
    axes[static_cast<size_t>(d % 2)][u.curve] += d < 2 ? 1 : -1;
  }
  for (auto& axis : axes) {
    for (auto it = axis.begin(); it != axis.end();) {
      it = it->second == 0 ? axis.erase(it) : std::next(it);
    }
  }
  return axes;
}

std::map<int, int> along(const std::vector<DirectedUse>& uses, int d) {
  std::map<int, int> out;
  for (const auto& u : uses) {
    if (((u.direction % 4) + 4) % 4 == ((d % 4) + 4) % 4) out[u.curve] += 1;
  }
  return out;
}

}  // namespace cooperage::submap
