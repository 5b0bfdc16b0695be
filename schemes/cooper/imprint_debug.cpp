#include "schemes/cooper/imprint_debug.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace cooperage::cooper {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

std::string subcaps_json(const std::vector<Subcap>& list) {
  std::string out = "[";
  for (size_t i = 0; i < list.size(); ++i) {
    out += std::string(i ? ", " : "") + "{\"id\": " + std::to_string(list[i].id) + ", \"loops\": [";
    for (size_t l = 0; l < list[i].loops.size(); ++l) {
      out += l ? ", [" : "[";
      for (size_t k = 0; k < list[i].loops[l].size(); ++k)
        out += (k ? ", " : "") + std::to_string(list[i].loops[l][k]);
      out += "]";
    }
    out += "]}";
  }
  return out + "]";
}

std::string ends_json(const BarrelEnds& ends, const std::string& why) {
  std::string out = "{\"xy\": {";
  bool first = true;
  char buf[80];
  for (const auto& [id, p] : ends.xy) {
    std::snprintf(buf, sizeof buf, "\"%d\": [%.17g, %.17g]", id, p.x(), p.y());
    out += std::string(first ? "" : ", ") + buf;
    first = false;
  }
  out += "},\n \"upper\": " + subcaps_json(ends.upper) +
         ",\n \"lower\": " + subcaps_json(ends.lower) + ",\n \"ribs\": [";
  for (size_t i = 0; i < ends.ribs.size(); ++i) {
    out += (i ? ", [" : "[") + std::to_string(ends.ribs[i].first) + ", " +
           std::to_string(ends.ribs[i].second) + "]";
  }
  out += "],\n \"fixed\": [";
  first = true;
  for (int v : ends.fixed) {
    out += (first ? "" : ", ") + std::to_string(v);
    first = false;
  }
  return out + "],\n \"why\": " + quoted(why) + "}\n";
}

bool write(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  return static_cast<bool>(f);
}

}  // namespace

bool write_imprint_debug(const std::string& name, const BarrelEnds& in, const ImprintResult& out) {
  const char* folder = std::getenv("COOPERAGE_DEBUG_IMPRINT");
  if (folder == nullptr || *folder == '\0') return false;
  const std::string base = std::string(folder) + "/" + name;
  bool ok = write(base + "-in.json", ends_json(in, "")) &&
            write(base + "-out.json", ends_json(out.ends, out.ok ? "" : out.why));
  for (size_t k = 0; k < out.trace.size() && ok; ++k) {
    ok = write(base + "-step" + std::to_string(k) + ".json",
               ends_json(out.trace[k].first,
                         "before step " + std::to_string(k) + ", after " + out.trace[k].second));
  }
  return ok;
}

int imprint_debug_steps() {
  const char* folder = std::getenv("COOPERAGE_DEBUG_IMPRINT");
  const char* steps = std::getenv("COOPERAGE_DEBUG_IMPRINT_STEPS");
  if (folder == nullptr || *folder == '\0' || steps == nullptr) return 0;
  return std::max(0, std::atoi(steps));
}

}  // namespace cooperage::cooper
