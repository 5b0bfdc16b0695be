#include "schemes/cooper/ring_spacing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace cooperage::cooper {
namespace {

// A size function's size at arc-length fraction s (linear between samples).
double size_at(const mesh::SizeFunction& f, double s) {
  size_t k = 1;
  while (k + 1 < f.at.size() && f.at[k] < s) ++k;
  const double w = (s - f.at[k - 1]) / std::max(1e-12, f.at[k] - f.at[k - 1]);
  return f.size[k - 1] + std::clamp(w, 0.0, 1.0) * (f.size[k] - f.size[k - 1]);
}

// A size function's sizes relative to their mean at arc-length fraction s
// (1 without one: uniform).
double relative_size(const mesh::SizeFunction* f, double s) {
  if (!f || f->empty()) return 1.0;
  double mean = 0;
  for (size_t k = 1; k < f->at.size(); ++k)
    mean += 0.5 * (f->size[k] + f->size[k - 1]) * (f->at[k] - f->at[k - 1]);
  return mean > 0 ? size_at(*f, s) / mean : 1.0;
}

// The finer of two profiles, sampled at kProfileSamples + 1
// fractions: both rings spaced by it keep node k facing node k and are as
// fine as either asks where it asks (a ring graded to a sliver corner on
// one cap only: campaign seed 20 case 85, a lug 0.04 proud of its block).
constexpr int kProfileSamples = 48;

// Sizes over their largest (1 without a function: uniform), so that a
// uniform ring leaves a graded one's profile as it is.
mesh::SizeFunction profile_of(const mesh::SizeFunction* f, bool reversed) {
  mesh::SizeFunction out;
  double largest = 0;
  if (f && !f->empty()) largest = *std::max_element(f->size.begin(), f->size.end());
  for (int i = 0; i <= kProfileSamples; ++i) {
    const double s = static_cast<double>(i) / kProfileSamples;
    out.at.push_back(s);
    out.size.push_back(largest > 0 ? size_at(*f, reversed ? 1.0 - s : s) / largest : 1.0);
  }
  return out;
}

}  // namespace

// Uniform pairs are dropped at once, so that the next pairs compare with
// uniform; sliver pairs are linked and combined per chain.
void space_alike_rings(const std::vector<AlongPair>& pairs, intervals::IntervalProblem& problem) {
  const auto& sizes = problem.size_functions();
  auto of = [&](int c) -> const mesh::SizeFunction* {
    const auto it = sizes.find(c);
    return it == sizes.end() ? nullptr : &it->second;
  };
  // Rings linked by unlike pairs, each with its orientation to the first.
  std::map<int, std::vector<std::pair<int, int>>> links;
  std::set<int> uniform;
  for (const AlongPair& p : pairs) {
    const mesh::SizeFunction* fa = of(p.a);
    const mesh::SizeFunction* fb = of(p.b);
    if (!fa && !fb) continue;
    double same = 0, reversed = 0;
    for (int i = 0; i <= 20; ++i) {
      const double s = i / 20.0;
      same = std::max(same, std::abs(relative_size(fa, s) - relative_size(fb, s)));
      reversed = std::max(reversed, std::abs(relative_size(fa, s) - relative_size(fb, 1 - s)));
    }
    if (std::min(same, reversed) <= 0.1) continue;
    if (!p.sliver_end) {  // dropped at once: the next pairs compare with uniform
      uniform.insert(p.a);
      uniform.insert(p.b);
      problem.drop_size_function(p.a);
      problem.drop_size_function(p.b);
      continue;
    }
    links[p.a].emplace_back(p.b, p.orientation);
    links[p.b].emplace_back(p.a, p.orientation);
  }
  std::set<int> done;
  for (const auto& entry : links) {
    if (done.count(entry.first)) continue;
    // Walk the component; orientation[c] = +1 / -1 relative to its first ring.
    std::map<int, int> orientation{{entry.first, 1}};
    std::vector<int> stack{entry.first};
    bool known = true;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      for (const auto& [d, o] : links.at(c)) {
        if (o == 0) known = false;
        const int od = orientation.at(c) * (o == 0 ? 1 : o);
        const auto [it, fresh] = orientation.emplace(d, od);
        if (fresh) {
          stack.push_back(d);
        } else if (it->second != od) {
          known = false;
        }
      }
    }
    for (const auto& ring : orientation) {
      done.insert(ring.first);
      if (uniform.count(ring.first)) known = false;
    }
    if (!known) {
      for (const auto& ring : orientation) uniform.insert(ring.first);
      continue;
    }
    mesh::SizeFunction finest;
    for (const auto& [c, o] : orientation) {
      const mesh::SizeFunction p = profile_of(of(c), o < 0);
      if (finest.empty()) {
        finest = p;
      } else {
        for (size_t i = 0; i < p.size.size(); ++i)
          finest.size[i] = std::min(finest.size[i], p.size[i]);
      }
    }
    for (const auto& [c, o] : orientation) {
      mesh::SizeFunction mine = finest;
      if (o < 0) {
        std::reverse(mine.size.begin(), mine.size.end());
      }
      problem.set_size_function(c, std::move(mine));
    }
  }
  for (int c : uniform) problem.drop_size_function(c);
}

}  // namespace cooperage::cooper
