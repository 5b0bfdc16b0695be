// The answer of a scheme's a-priori test: can it mesh this entity, how well
// (score, higher is better), and why, in a sentence for a person.
#pragma once

#include <string>

namespace cooperage::scheme {

struct Applicability {
  bool ok = false;
  double score = 0.0;  ///< in [0, 1]; compares schemes on one entity
  std::string why;     ///< "surface 12: 6 END vertices, map needs 4"

  static Applicability yes(double score, std::string why = {}) {
    return {true, score, std::move(why)};
  }
  static Applicability no(std::string why) { return {false, 0.0, std::move(why)}; }
};

}  // namespace cooperage::scheme
