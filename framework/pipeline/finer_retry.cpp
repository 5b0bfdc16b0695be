#include "framework/pipeline/finer_retry.h"

#include "framework/core/text.h"

#include <cmath>
#include <optional>

namespace cooperage::pipeline {
namespace {

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

}  // namespace

std::vector<int> halve_failed_volumes(const std::vector<Verdict>& verdicts,
                                      io::MeshSettings& settings,
                                      std::map<int, FinerRetry>& retries) {
  std::vector<int> halved;
  for (const Verdict& v : verdicts) {
    if (v.state != Verdict::State::Refused || !v.finer_may_help || v.entity.dim != 3) continue;
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

void report_finer_retries(const std::map<int, FinerRetry>& retries, MeshResult& result) {
  std::vector<Warning> warnings;
  for (Verdict& v : result.verdicts) {
    const auto it = retries.find(v.entity.id);
    if (v.entity.dim != 3 || it == retries.end()) continue;
    const FinerRetry& r = it->second;
    if (v.state == Verdict::State::Refused) {
      v.hint = "meshing it again at " + fraction(r.asked, r.size) + " the size (" +
               number_text(r.size) + ") failed too; " + v.hint;
      continue;
    }
    warnings.push_back({v.entity, "meshed at size " + number_text(r.size) + ", " +
                                      fraction(r.asked, r.size) + " the size asked for (" +
                                      number_text(r.asked) +
                                      "), at which it failed: " + clip(r.first_reason, 240)});
  }
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
}

}  // namespace cooperage::pipeline
