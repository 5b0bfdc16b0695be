#include "run_report.h"

#include "framework/core/text.h"
#include "framework/decompose/report_text.h"

#include <cstdio>
#include <map>
#include <vector>

namespace cooperage::app {
namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::string entity_name(const EntityRef& entity, const std::vector<int>& origin) {
  const int id = entity.id;
  if (entity.dim != 3 || id < 1 || static_cast<std::size_t>(id) > origin.size() ||
      origin[static_cast<std::size_t>(id - 1)] == id)
    return entity.name();
  return entity.name() + " (input volume " +
         std::to_string(origin[static_cast<std::size_t>(id - 1)]) + ")";
}

void write_verdicts(const std::vector<pipeline::Verdict>& verdicts, std::ostream& out,
                    const std::vector<int>& origin) {
  using State = pipeline::Verdict::State;
  for (const auto& v : verdicts) {
    out << entity_name(v.entity, origin) << ": ";
    switch (v.state) {
      case State::Meshed: out << "meshed"; break;
      case State::Refused: out << "refused: " << clip(v.reason, 200); break;
      case State::Deviates: out << "failed the volume check: " << clip(v.reason, 200); break;
    }
    out << "\n";
  }
}

void write_run_report(const pipeline::RunResult& result, std::ostream& out) {
  std::map<std::pair<int, int>, double> seconds;
  std::map<std::pair<int, int>, std::string> schemes;
  for (const auto& t : result.mesh.timings) {
    seconds[{t.dim, t.id}] = t.seconds;
    schemes[{t.dim, t.id}] = t.scheme;
  }
  for (const auto& l : decompose::report_lines(result.decomposition))
    out << "decomposed " << l << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-12s %-8s %-6s %10s %8s %8s %8s %8s %9s\n", "entity", "scheme",
                "type", "elements", "min SJ", "mean SJ", "max SJ", "inverted", "time [s]");
  out << line;
  std::vector<std::size_t> histogram;
  double lo = -1, hi = 1;
  for (const auto& b : result.quality.blocks) {
    const auto* sj = b.find("scaled_jacobian");
    const std::string entity = (b.dim == 3 ? "volume " : "surface ") + std::to_string(b.id);
    std::snprintf(line, sizeof line, "%-12s %-8s %-6s %10zu %8.4f %8.4f %8.4f %8zu %9.3f\n",
                  entity.c_str(), schemes[{b.dim, b.id}].c_str(),
                  std::string(quality::to_string(b.type)).c_str(), b.count, sj ? sj->min : 0.0,
                  sj ? sj->mean : 0.0, sj ? sj->max : 0.0, sj ? sj->inverted : std::size_t{0},
                  seconds[{b.dim, b.id}]);
    out << line;
    if (!sj) continue;
    if (histogram.empty()) histogram.assign(sj->histogram.size(), 0);
    lo = sj->histogram_lo;
    hi = sj->histogram_hi;
    for (std::size_t i = 0; i < sj->histogram.size() && i < histogram.size(); ++i) {
      histogram[i] += sj->histogram[i];
    }
  }
  if (!histogram.empty()) {
    out << "scaled Jacobian histogram, " << histogram.size() << " bins over [" << fmt("%g", lo)
        << ", " << fmt("%g", hi) << "]:";
    for (std::size_t n : histogram) out << " " << n;
    out << "\n";
  }
  out << "nodes " << result.mesh.mesh.node_count() << ", hexes " << result.mesh.mesh.hex_count()
      << ", wedges " << result.mesh.mesh.wedge_count() << ", quads "
      << result.mesh.mesh.quad_count() << ", triangles " << result.mesh.mesh.tri_count() << "\n";
  for (const auto& c : result.quality.checks) {
    out << "quality " << c.check.metric;
    if (c.check.min) out << " >= " << fmt("%g", *c.check.min);
    if (c.check.max) out << " <= " << fmt("%g", *c.check.max);
    out << ": " << c.violations << " elements outside"
        << (c.failed ? " -- FAILED" : (c.violations ? " (warning)" : ", ok")) << "\n";
  }
  if (!result.stages.empty()) {
    out << "time [s]:";
    for (const auto& st : result.stages)
      out << " " << st.stage << " " << fmt("%.3f", st.seconds) << ",";
    double total = 0;
    for (const auto& st : result.stages) total += st.seconds;
    out << " total " << fmt("%.3f", total) << "\n";
  }
  if (result.mesh.verdicts.size() > 1 || result.mesh.incomplete())
    write_verdicts(result.mesh.verdicts, out, result.decomposition.origin);
  for (const auto& w : result.mesh.warnings) out << "warning: " << clip(w.text(), 300) << "\n";
  for (const auto& f : result.written) out << "wrote " << f << "\n";
  if (result.exports_skipped)
    out << "exports skipped: "
        << (result.quality.failed() ? "a quality check failed" : "a volume check failed") << "\n";
  else if (result.mesh.incomplete() && !result.written.empty())
    out << "partial: only the volumes that meshed were written\n";
}

}  // namespace cooperage::app
