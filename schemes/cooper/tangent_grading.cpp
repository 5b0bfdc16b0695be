#include "schemes/cooper/tangent_grading.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace cooperage::cooper {

void grade_tangent_ribs(const VolumeFacts& facts, const SideLattice& lattice,
                        intervals::IntervalProblem& problem) {
  // Per curve: the first interval wanted at its start and at its end.
  std::map<int, std::pair<double, double>> ends;
  for (const TangentDeparture& d : lattice.graded) {
    auto& e = ends[d.along];
    const bool at_start = facts.curves.at(d.along).start == d.vertex;
    double& v = at_start ? e.first : e.second;
    v = std::max(v, d.first_size);
  }
  for (const auto& [id, e] : ends) {
    const auto it = problem.curves().find(id);
    if (it == problem.curves().end() || it->second.hard()) continue;  // the user's count holds
    const intervals::Curve& c = it->second;
    const double length = facts.curves.at(id).length;
    // The count the solver aims at; the long first interval(s) take their
    // length and the rest share what is left, so the first interval is
    // exactly as long as needed with that count (and longer with fewer).
    const int n = std::max(c.min, static_cast<int>(std::lround(std::max(1.0, c.target()))));
    const double a = std::min(e.first, length), b = std::min(e.second, length);
    const auto cap_at = [&](int most) {
      most = std::max(c.min, most);
      problem.add_linear({{id, 1}}, intervals::Sense::LessEqual, most,
                         "cooper: curve " + std::to_string(id) +
                             " leaves a cap tangentially: at most " + std::to_string(most) +
                             " intervals keep its first one long enough");
    };
    if (std::max(a, b) * n <= length) {  // even intervals at that count are long enough
      cap_at(static_cast<int>(std::floor(length / std::max(a, b))));
      continue;
    }
    const int graded = (a > 0) + (b > 0);
    const double rest = length - a - b;
    mesh::SizeFunction f;
    int most = n;  // the sizes integrate to n: more intervals would shorten the first again
    if (n <= graded || rest <= 0) {  // the long ends fill the curve: one interval
      f.at = {0.0, 1.0};
      f.size = {length, length};
      most = 1;
    } else {
      const double h = rest / (n - graded);
      const double s0 = std::max(a, h), s1 = std::max(b, h);
      const double fa = a / length, fb = b / length;
      const double ramp = 0.01 * h / length;  // a step, kept piecewise linear
      f.at = {0.0, fa, std::min(fa + ramp, 1.0 - fb), std::max(1.0 - fb - ramp, fa), 1.0 - fb, 1.0};
      f.size = {s0, s0, h, h, s1, s1};
    }
    problem.set_size_function(id, f);
    cap_at(most);
  }
}

}  // namespace cooperage::cooper
