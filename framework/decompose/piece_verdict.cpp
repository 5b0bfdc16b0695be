#include "framework/decompose/piece_verdict.h"

#include "framework/scheme/refusals.h"

namespace cooperage::decompose {

PieceVerdict best_scheme(const geom::Model& model, int volume, const scheme::Registry& registry,
                         const scheme::Settings* settings) {
  PieceVerdict out;
  const scheme::VolumeView view{model, volume, nullptr, settings};
  // Wedge and mixed volumes take only the schemes that make wedges, as the
  // selector does: a piece the volume map would take is no answer then.
  const bool wedges = settings && settings->elements(volume) != io::ElementKind::Hex;
  std::vector<std::pair<std::string, std::string>> refusals;
  for (const scheme::VolumeScheme* s : registry.volume_schemes()) {
    if (wedges && !s->makes_wedges()) continue;
    const scheme::Applicability a = s->applicable(view);
    if (a.ok) {
      if (!out.ok || a.score > out.score) {
        out.ok = true;
        out.scheme = std::string(s->name());
        out.score = a.score;
      }
    } else {
      refusals.emplace_back(std::string(s->name()), a.why);
    }
  }
  if (!out.ok) out.why = scheme::join_refusals(refusals);
  if (!out.ok && out.why.empty()) out.why = "no volume scheme registered";
  return out;
}

std::string deciding_reason(const std::string& why) {
  // Cooper's words (schemes/cooper/plan_volume.cpp); without them, all.
  const std::string marker = "(the one that got furthest: ";
  const size_t at = why.find(marker);
  if (at == std::string::npos) return why;
  const size_t start = at + marker.size();
  int depth = 1;
  for (size_t i = start; i < why.size(); ++i) {
    if (why[i] == '(') ++depth;
    if (why[i] == ')' && --depth == 0) return why.substr(start, i - start);
  }
  return why.substr(start);  // cut short: what there is
}

}  // namespace cooperage::decompose
