#include "framework/decompose/report_text.h"

#include <cstdio>

namespace cooperage::decompose {
namespace {

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string ids(const std::vector<int>& list) {
  std::string out;
  for (size_t k = 0; k < list.size(); ++k) out += (k ? ", " : "") + std::to_string(list[k]);
  return out;
}

}  // namespace

std::vector<std::string> report_lines(const Report& report) {
  std::vector<std::string> out;
  for (const VolumeDecomposition& v : report.volumes) {
    out.push_back("volume " + std::to_string(v.volume) +
                  (v.name.empty() ? "" : " (" + v.name + ")") + ": cut into volumes " +
                  ids(v.pieces) + " (" + std::to_string(v.cuts.size()) + " cut" +
                  (v.cuts.size() == 1 ? "" : "s") + ", " + std::to_string(v.tried) +
                  " tried); as one volume: " + v.refusal + " (" + v.why + ")");
    for (size_t k = 0; k < v.cuts.size(); ++k) {
      const AppliedCut& c = v.cuts[k];
      // `through` names the part's entities, whichever piece was cut.
      out.push_back("  cut " + std::to_string(k + 1) + (c.depth ? " (of a piece)" : "") + ": " +
                    describe(c.surface) + ", the " + c.through + " -> " + std::to_string(c.pieces) +
                    " pieces, thinnest " + num(c.thinnest));
    }
  }
  return out;
}

}  // namespace cooperage::decompose
