#include "framework/decompose/same_part.h"

#include <algorithm>
#include <cmath>

namespace cooperage::decompose {
namespace {

double total_volume(const geom::Model& m) {
  double volume = 0.0;
  for (const geom::Volume& v : m.volumes()) volume += v.volume;
  return volume;
}

bool near(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

}  // namespace

double skin_area(const geom::Model& model) {
  double area = 0.0;
  for (const geom::Surface& s : model.surfaces()) {
    if (s.volumes.size() == 1) area += s.area;
  }
  return area;
}

bool same_skin_and_volume(const geom::Model& pieces, const geom::Model& part) {
  return near(skin_area(pieces), skin_area(part)) && near(total_volume(pieces), total_volume(part));
}

}  // namespace cooperage::decompose
