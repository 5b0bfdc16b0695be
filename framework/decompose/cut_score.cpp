#include "framework/decompose/cut_score.h"

#include <algorithm>
#include <cmath>

namespace cooperage::decompose {
namespace {

double thickness_term(double thinnest) { return std::clamp(thinnest, 0.0, 4.0) / 4.0; }

}  // namespace

double complete_score(const CutOutcome& o) {
  // The fractional terms add up to at most 0.9 < 1, the cost of a piece.
  return -static_cast<double>(o.pieces) + 0.5 * o.min_score + 0.2 * o.mean_score +
         0.2 * thickness_term(o.thinnest);
}

double partial_score(const CutOutcome& o) {
  return o.meshable_fraction - 0.1 * o.failing + 0.05 * thickness_term(o.thinnest);
}

bool better(double a, double b) { return a > b + 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

}  // namespace cooperage::decompose
