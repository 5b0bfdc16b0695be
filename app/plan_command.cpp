#include "plan_command.h"

#include "json_writer.h"

#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

namespace cooperage::app {
namespace {

void write_text(const selector::Selection& sel, bool intervals_checked, std::ostream& out) {
  auto entity = [&](const selector::Choice& c) {
    out << (c.dim == 3 ? "volume " : "surface ") << c.id << ": "
        << (c.scheme == scheme::kMeshedByVolume ? std::string("meshed by its volume") : c.scheme)
        << "  -- " << c.reason << "\n";
    for (const auto& k : c.candidates) out << "    " << selector::describe(k) << "\n";
  };
  if (!sel.volumes.empty()) out << "volumes\n";
  for (const auto& c : sel.volumes) entity(c);
  out << "surfaces\n";
  for (const auto& c : sel.surfaces) entity(c);
  for (const auto& r : sel.relaxations) out << "relaxed " << r << "\n";
  if (!intervals_checked) out << "interval feasibility not checked: no element size given\n";
}

void write_json(const selector::Selection& sel, bool intervals_checked, std::ostream& out) {
  JsonWriter j(out);
  auto entities = [&](const std::vector<selector::Choice>& list) {
    j.begin_array();
    for (const auto& c : list) {
      j.begin_object();
      j.key("id");
      j.value(c.id);
      j.key("scheme");
      j.value(c.scheme);
      j.key("reason");
      j.value(c.reason);
      j.key("pinned");
      j.value(c.pinned);
      j.key("candidates");
      j.begin_array();
      for (const auto& k : c.candidates) {
        j.begin_object();
        j.key("scheme");
        j.value(k.scheme);
        j.key("ok");
        j.value(k.applicability.ok);
        j.key("score");
        j.value(k.applicability.score);
        j.key("why");
        j.value(k.applicability.why);
        j.end_object();
      }
      j.end_array();
      j.end_object();
    }
    j.end_array();
  };
  j.begin_object();
  j.key("volumes");
  entities(sel.volumes);
  j.key("surfaces");
  entities(sel.surfaces);
  j.key("relaxations");
  j.begin_array();
  for (const auto& r : sel.relaxations) j.value(r);
  j.end_array();
  j.key("intervals_checked");
  j.value(intervals_checked);
  j.end_object();
  out << "\n";
}

}  // namespace

int run_plan(const std::string& file, std::optional<double> size, bool json,
             const std::vector<std::string>& plugins, std::ostream& out) {
  const pipeline::PlanInput input = pipeline::plan_input(file, size);
  const geom::Model& model = input.model;
  const io::MeshSettings& settings = input.settings;
  scheme::Registry registry;
  register_schemes(registry, builtin_options(settings), run_plugins(plugins, input.plugins));
  selector::SelectOptions options;
  options.check_intervals = settings.size.has_value();
  const selector::Selection sel = selector::select_schemes(model, registry, settings, options);
  if (json) {
    write_json(sel, options.check_intervals, out);
  } else {
    write_text(sel, options.check_intervals, out);
  }
  return 0;
}

}  // namespace cooperage::app
