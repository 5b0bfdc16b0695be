#include "framework/pipeline/finer_retry.h"

#include "framework/core/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace cooperage::pipeline {
namespace {

// "what was tried; the scheme's hint", or what was tried alone when the
// scheme gave no hint (a lattice that does not fit its face): no "; " left
// dangling at the end of the message.
std::string then(const std::string& tried, const std::string& hint) {
  return hint.empty() ? tried : tried + "; " + hint;
}

// A scaled Jacobian for a message, as the worst-element warning has it.
std::string quality_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

std::optional<double> size_of(const io::MeshSettings& settings, int volume) {
  for (const io::VolumeSetting& v : settings.volumes)
    if (v.id == volume && v.sizing.size) return v.sizing.size;
  return settings.size;
}

io::VolumeSetting& setting_of(io::MeshSettings& settings, int volume) {
  for (io::VolumeSetting& v : settings.volumes)
    if (v.id == volume) return v;
  io::VolumeSetting added;
  added.id = volume;
  settings.volumes.push_back(added);
  return settings.volumes.back();
}

// "half", "a quarter", "1/8" of the size asked for.
std::string fraction(double asked, double size) {
  const long n = std::lround(asked / size);
  if (n == 2) return "half";
  if (n == 4) return "a quarter";
  return "1/" + std::to_string(n);
}

// "(0, 0, -1)", as `cooperage plan` writes a sweep direction.
std::string vector_text(const geom::Vec3& v) {
  auto c = [](double x) { return number_text(std::abs(x) < 5e-4 ? 0.0 : x); };
  return "(" + c(v.x()) + ", " + c(v.y()) + ", " + c(v.z()) + ")";
}

}  // namespace

std::vector<int> halve_failed_volumes(const std::vector<Verdict>& verdicts,
                                      io::MeshSettings& settings,
                                      std::map<int, FinerRetry>& retries,
                                      const std::vector<int>* only) {
  std::vector<int> halved;
  for (const Verdict& v : verdicts) {
    if (v.state != Verdict::State::Refused || !v.finer_may_help || v.entity.dim != 3) continue;
    if (only && std::find(only->begin(), only->end(), v.entity.id) == only->end()) continue;
    const std::optional<double> size = size_of(settings, v.entity.id);
    if (!size) continue;  // sized by interval counts only: nothing to halve
    auto [it, first] = retries.try_emplace(v.entity.id);
    if (first) {
      it->second.asked = *size;
      it->second.first_reason = v.reason;
    }
    it->second.size = 0.5 * *size;
    setting_of(settings, v.entity.id).sizing.size = it->second.size;
    halved.push_back(v.entity.id);
  }
  return halved;
}

void note_planned_sweeps(const SchemePlan& plan, const io::MeshSettings& settings,
                         std::map<int, FinerRetry>& retries) {
  for (auto& [id, r] : retries) {
    bool hinted = false;
    for (const io::VolumeSetting& v : settings.volumes)
      hinted = hinted || (v.id == id && (v.direction || !v.sources.empty() || !v.targets.empty()));
    const auto entry = plan.volumes.find(id);
    if (hinted || entry == plan.volumes.end() || !entry->second.data) continue;
    if (const auto d = entry->second.data->straight_sweep())
      r.planned_sweep = geom::Vec3((*d)[0], (*d)[1], (*d)[2]);
  }
}

std::vector<int> turn_failed_sweeps(const std::vector<Verdict>& verdicts,
                                    io::MeshSettings& settings,
                                    std::map<int, FinerRetry>& retries) {
  std::vector<int> turned;
  for (const Verdict& v : verdicts) {
    if (v.state != Verdict::State::Refused || !v.finer_may_help || v.entity.dim != 3) continue;
    const auto it = retries.find(v.entity.id);
    if (it == retries.end() || !it->second.planned_sweep || it->second.turned) continue;
    FinerRetry& r = it->second;
    r.turned = true;
    r.size = r.asked;
    io::VolumeSetting& s = setting_of(settings, v.entity.id);
    s.sizing.size = r.asked;
    s.direction = -*r.planned_sweep;
    turned.push_back(v.entity.id);
  }
  return turned;
}

std::optional<double> failing_scaled_jacobian_floor(const std::vector<io::QualityCheck>& checks) {
  std::optional<double> floor;
  for (const io::QualityCheck& c : checks) {
    if (c.metric != "scaled_jacobian" || c.action != io::QualityCheck::Action::Fail || !c.min)
      continue;
    floor = std::max(floor.value_or(*c.min), *c.min);
  }
  return floor;
}

std::optional<double> worst_scaled_jacobian(const MeshResult& result, int volume) {
  std::optional<double> worst;
  for (const BlockReport& b : result.quality.blocks) {
    if (b.dim != 3 || b.id != volume) continue;
    const quality::MetricSummary* sj = b.find("scaled_jacobian");
    if (sj && sj->count > 0) worst = std::min(worst.value_or(sj->min), sj->min);
  }
  return worst;
}

std::vector<int> halve_poor_volumes(const MeshResult& result, double floor,
                                    io::MeshSettings& settings,
                                    std::map<int, FinerRetry>& retries) {
  std::vector<int> halved;
  for (const Verdict& v : result.verdicts) {
    if (v.state != Verdict::State::Meshed || v.entity.dim != 3) continue;
    const std::optional<double> worst = worst_scaled_jacobian(result, v.entity.id);
    if (!worst || *worst >= floor) continue;
    const std::optional<double> size = size_of(settings, v.entity.id);
    if (!size) continue;  // sized by interval counts only: nothing to halve
    auto [it, first] = retries.try_emplace(v.entity.id);
    if (first) {
      it->second.asked = *size;
      it->second.for_quality = true;
      it->second.first_reason = "its worst element's scaled Jacobian was " + number_text(*worst) +
                                ", below the minimum " + number_text(floor) +
                                " of a failing <quality> check";
    }
    it->second.size = 0.5 * *size;
    setting_of(settings, v.entity.id).sizing.size = it->second.size;
    halved.push_back(v.entity.id);
  }
  return halved;
}

std::vector<int> turn_poor_sweeps(const MeshResult& result, double below,
                                  io::MeshSettings& settings, std::map<int, FinerRetry>& retries) {
  std::vector<int> turned;
  for (const Verdict& v : result.verdicts) {
    if (v.state != Verdict::State::Meshed || v.entity.dim != 3) continue;
    const std::optional<double> worst = worst_scaled_jacobian(result, v.entity.id);
    const std::optional<double> size = size_of(settings, v.entity.id);
    if (!worst || *worst >= below || !size) continue;
    std::map<int, FinerRetry> one{{v.entity.id, FinerRetry{}}};
    note_planned_sweeps(result.plan, settings, one);
    FinerRetry& r = one.begin()->second;
    if (!r.planned_sweep) continue;  // not a straight sweep, or one the journal directs
    r.asked = r.size = *size;
    r.turned = r.for_quality = true;
    r.planned_worst = worst;
    setting_of(settings, v.entity.id).direction = -*r.planned_sweep;
    retries[v.entity.id] = r;
    turned.push_back(v.entity.id);
  }
  return turned;
}

std::vector<int> halve_volumes_again(const std::vector<int>& volumes, io::MeshSettings& settings,
                                     std::map<int, FinerRetry>& retries) {
  for (int volume : volumes) {
    FinerRetry& r = retries.at(volume);
    r.size *= 0.5;
    setting_of(settings, volume).sizing.size = r.size;
  }
  return volumes;
}

void report_finer_retries(const std::map<int, FinerRetry>& retries, MeshResult& result) {
  std::vector<Warning> warnings;
  for (Verdict& v : result.verdicts) {
    const auto it = retries.find(v.entity.id);
    if (v.entity.dim != 3 || it == retries.end()) continue;
    const FinerRetry& r = it->second;
    const std::string other_way =
        r.planned_sweep ? "sweeping it the other way, along " + vector_text(-*r.planned_sweep)
                        : std::string();
    if (r.turned && v.state == Verdict::State::Refused) {
      v.hint = then("meshing it again at smaller sizes, and " + other_way + ", failed too", v.hint);
      continue;
    }
    if (r.turned && r.for_quality && r.planned_worst) {
      const std::optional<double> worst = worst_scaled_jacobian(result, v.entity.id);
      warnings.push_back({v.entity, "meshed " + other_way + ", at the size asked for (" +
                                        number_text(r.asked) + "): its worst element's scaled " +
                                        "Jacobian is " + quality_text(worst.value_or(0)) +
                                        ", where along " + vector_text(*r.planned_sweep) +
                                        " it was " + quality_text(*r.planned_worst)});
      continue;
    }
    if (r.turned) {
      const std::string at =
          r.size == r.asked ? "at the size asked for (" + number_text(r.asked) + ")"
                            : "at size " + number_text(r.size) + ", " + fraction(r.asked, r.size) +
                                  " the size asked for (" + number_text(r.asked) + ")";
      warnings.push_back({v.entity, "meshed " + other_way + ", " + at + "; along " +
                                        vector_text(*r.planned_sweep) +
                                        " it failed at the size asked for and at smaller ones: " +
                                        clip(r.first_reason, 240)});
      continue;
    }
    if (v.state == Verdict::State::Refused) {
      v.hint = then("meshing it again at " + fraction(r.asked, r.size) + " the size (" +
                        number_text(r.size) + ") failed too",
                    v.hint);
      continue;
    }
    warnings.push_back({v.entity, "meshed at size " + number_text(r.size) + ", " +
                                      fraction(r.asked, r.size) + " the size asked for (" +
                                      number_text(r.asked) + "), " +
                                      (r.for_quality ? "where " : "at which it failed: ") +
                                      clip(r.first_reason, 240)});
  }
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
}

}  // namespace cooperage::pipeline
