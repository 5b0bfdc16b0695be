#include "framework/decompose/search_cuts.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/decompose/cut_candidates.h"
#include "framework/decompose/cut_score.h"
#include "framework/decompose/piece_verdict.h"
#include "framework/decompose/volume_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>

#include <tbb/parallel_for.h>

namespace cooperage::decompose {
namespace {

// One candidate cut, evaluated.
struct Evaluated {
  const CutCandidate* candidate = nullptr;
  occ::SolidPieces pieces;
  std::vector<PieceVerdict> verdicts;
  CutOutcome outcome;
  double thinnest = 0.0;  ///< model units
  double score = 0.0;
  geom::Model model;
};

// Thinnest piece across the cut (model units): each piece lies on one side;
// its thickness is the largest distance of its points from the cut. From
// the solids, before their model is built: a sliver costs only the split.
double thinnest_piece(const occ::SolidPieces& pieces, const CutSurface& cut) {
  double thinnest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < pieces.size(); ++k) {
    const Span s = span(cut, pieces.boundary_samples(k, kSamplesPerCurve));
    thinnest = std::min(thinnest, std::max(-s.below, s.above));
  }
  return thinnest;
}

CutOutcome summarise(const geom::Model& pieces, const std::vector<PieceVerdict>& verdicts,
                     double thinnest, double size) {
  CutOutcome o;
  o.pieces = static_cast<int>(verdicts.size());
  o.thinnest = thinnest / size;
  double total = 0.0, meshable = 0.0, sum = 0.0;
  int ok = 0;
  o.min_score = 1.0;
  for (size_t k = 0; k < verdicts.size(); ++k) {
    const double vol = pieces.volumes()[k].volume;
    total += vol;
    if (!verdicts[k].ok) {
      ++o.failing;
      continue;
    }
    ++ok;
    meshable += vol;
    sum += verdicts[k].score;
    o.min_score = std::min(o.min_score, verdicts[k].score);
  }
  if (ok == 0) o.min_score = 0.0;
  o.mean_score = ok ? sum / ok : 0.0;
  o.meshable_fraction = total > 0 ? meshable / total : 0.0;
  return o;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

// "20 bspline, 2 torus": the geometry of a volume's faces, by kind.
std::string surface_kinds(const geom::Model& model, int volume) {
  std::map<geom::SurfaceType, int> count;
  for (int s : model.surfaces_of(volume)) {
    const auto& g = model.surface(s).geometry;
    ++count[g ? g->type() : geom::SurfaceType::Other];
  }
  std::string out;
  for (const auto& [type, n] : count)
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + geom::to_string(type);
  return out;
}

// One cut's pieces judged: their thickness across the cut, their model and
// a-priori verdicts. This reads the shapes only, so cuts are judged in
// parallel. Nullopt for a sliver or a model the kernel cannot build.
std::optional<Evaluated> judge(occ::SolidPieces pieces, const CutCandidate& c, double size,
                               const scheme::Registry& registry, const scheme::Settings* settings) {
  Evaluated e;
  e.candidate = &c;
  e.pieces = std::move(pieces);
  try {
    e.thinnest = thinnest_piece(e.pieces, c.surface);
    if (e.thinnest < size) return std::nullopt;  // a sliver thinner than one element layer
    e.model = e.pieces.build_model(false);
  } catch (const MeshingError&) {
    return std::nullopt;
  }
  for (const geom::Volume& v : e.model.volumes())
    e.verdicts.push_back(best_scheme(e.model, v.id, registry, settings));
  e.outcome = summarise(e.model, e.verdicts, e.thinnest, size);
  return e;
}

// A cut's surface in a refusal, after the face or edge it runs through:
// " (plane y = 2)"; an oblique one's origin and normal (60 characters) would
// push the reason past what a line of the command shows, and follow from
// the face, or the curve and direction, named (the cuts of a decomposition
// that succeeds are listed in full).
std::string in_brief(const CutSurface& cut) {
  const std::string d = describe(cut);
  return d.size() <= 32 ? " (" + d + ")" : "";
}

AppliedCut applied(const Evaluated& e, int depth, double thinnest) {
  return {e.candidate->surface, e.candidate->through, depth, e.outcome.pieces, thinnest};
}

}  // namespace

std::string CutSearch::failure() const {
  std::string out = "tried " + std::to_string(tried_) + " cut" + (tried_ == 1 ? "" : "s");
  // Cuts come from the planes and cylinders of its faces and from its
  // straight and circular edges along their axes; the meridians of its
  // cylinders and tori come last.
  if (candidates_ == 0 && tried_ == 0)
    return out + "; none of its faces is a plane, a cylinder or a torus to cut along (" +
           face_kinds_ + ")";
  if (crossing_ == 0) {
    return out + "; no cut through its faces or edges leaves pieces at least one element layer (" +
           number(options_.size) + ") thick (the thickest leaves " + number(thickest_) +
           " on its thinner side: a size of at most " + number(thickest_) + " lets it cut)";
  }
  if (!conflict_.empty()) {
    out += "; " + conflict_;
    if (conflicts_ > 1)
      out += " (nor do " + std::to_string(conflicts_ - 1) + " other sets of sweepable pieces)";
  }
  if (!best_partial_.empty()) out += "; " + best_partial_;
  if (conflict_.empty() && best_partial_.empty()) out += "; no cut leaves sweepable pieces";
  return out;
}

std::string CutSearch::check_in(const occ::SolidPieces& pieces, const geom::Model* alone,
                                const Context& context) {
  // The pieces of one split share their cut faces already; among other
  // solids they are imprinted and merged with them first.
  geom::Model built;
  if (context) {
    built = context(pieces).build_model(true, true);
  } else if (!alone) {
    built = pieces.build_model(true, true);
  }
  const geom::Model& model = alone && !context ? *alone : built;
  const std::string reason = check_(model, last_resort_);
  return reason.empty() ? reason : part_ids_.translate(reason, model);
}

std::optional<SolidPlan> CutSearch::solve_turned(const occ::SolidPieces& solid) {
  const geom::Model model = solid.build_model(false);
  if (model.volumes().size() != 1) return std::nullopt;
  const double size = options_.size;
  for (CoreCut c : core_candidates(model, 1)) {
    if (tried_ + 2 > options_.max_cuts) break;
    c.core.through = part_ids_.translate(c.core.through, model);
    c.meridian.through = part_ids_.translate(c.meridian.through, model);
    tried_ += 2;
    try {
      const occ::SolidPieces cored = solid.split(0, c.core.surface);
      if (cored.size() != 2) continue;  // the core misses the solid: a bore
      const geom::Model two = cored.build_model(false);
      // The tube: the piece no scheme takes (the core sweeps along the axis).
      int tube = -1;
      for (const geom::Volume& v : two.volumes()) {
        if (!best_scheme(two, v.id, registry_, options_.settings).ok) {
          if (tube >= 0) tube = -2;
          if (tube == -1) tube = v.id - 1;
        }
      }
      if (tube < 0) continue;
      const occ::SolidPieces halves = cored.split(tube, c.meridian.surface);
      if (halves.size() < 2) continue;
      const occ::SolidPieces pieces = cored.replace(tube, halves);
      const geom::Model all = pieces.build_model(false);
      bool ok = true;
      for (const geom::Volume& v : all.volumes())
        ok = ok && best_scheme(all, v.id, registry_, options_.settings).ok;
      // The core is as thick as its radius (its samples lie on the cut).
      const double thin_core = c.core.surface.radius;
      const double thin_half = thinnest_piece(pieces, c.meridian.surface);
      if (!ok || thin_core < size || thin_half < size) continue;
      const std::string reason = check_in(pieces, &all, nullptr);
      log::info("decompose: " + c.core.through + " and " + c.meridian.through +
                (reason.empty() ? " plan" : " do not plan: " + reason));
      if (!reason.empty()) continue;
      return SolidPlan{pieces,
                       {{c.core.surface, c.core.through, 0, 2, thin_core},
                        {c.meridian.surface, c.meridian.through, 1, halves.size(), thin_half}}};
    } catch (const MeshingError&) {
      continue;  // the kernel could not make a cut
    }
  }
  return std::nullopt;
}

std::optional<SolidPlan> CutSearch::solve(const occ::SolidPieces& solid, int depth,
                                          const std::vector<CutCandidate>& inherited,
                                          const Context& context) {
  const geom::Model model = solid.build_model(false);
  if (model.volumes().size() != 1) return std::nullopt;
  if (best_scheme(model, 1, registry_, options_.settings).ok) return SolidPlan{solid, {}};
  if (depth >= options_.max_depth) return std::nullopt;

  const double size = options_.size;
  const std::vector<geom::Vec3> samples = volume_samples(model, 1);
  // The piece's own candidates, then those of the solids it was cut from;
  // in the second pass the meridian planes first (the first pass spent
  // part of the budget on the others already).
  std::vector<CutCandidate> candidates =
      last_resort_ ? meridian_candidates(model, 1) : std::vector<CutCandidate>();
  std::vector<CutCandidate> more = cut_candidates(model, 1);
  // Named by the part's entities (the inherited ones are already).
  for (CutCandidate& c : candidates) c.through = part_ids_.translate(c.through, model);
  for (CutCandidate& c : more) c.through = part_ids_.translate(c.through, model);
  more.insert(more.end(), inherited.begin(), inherited.end());
  for (const CutCandidate& c : more) {
    bool known = false;
    for (const CutCandidate& k : candidates)
      known = known || same_surface(k.surface, c.surface, 1e-6);
    if (!known) candidates.push_back(c);
  }
  if (depth == 0 && !last_resort_) {
    candidates_ = static_cast<int>(candidates.size());
    face_kinds_ = surface_kinds(model, 1);
  }
  // The cuts given to the kernel, chosen before any is made: the budget and
  // the counters are then those of any thread count.
  std::vector<const CutCandidate*> chosen;
  for (const CutCandidate& c : candidates) {
    if (tried_ >= options_.max_cuts) break;
    // A cut must leave at least one element layer on each side.
    const Span s = span(c.surface, samples);
    if (depth == 0) thickest_ = std::max(thickest_, std::min(-s.below, s.above));
    if (s.below > -size || s.above < size) continue;
    if (depth == 0) ++crossing_;
    ++tried_;
    chosen.push_back(&c);
  }
  // The kernel's cuts one after another, in the candidates' order: a split
  // may change the solid it is given in place (a vertex's tolerance, an
  // edge's p-curve on the cut), so each sees what the ones before left, as
  // on one thread. Copying instead (the kernel's non-destructive mode) made
  // occt_Pump_TopCover's search 40 % slower: its faces' remembered measures
  // were lost with the copies.
  std::vector<std::optional<occ::SolidPieces>> cut(chosen.size());
  for (size_t i = 0; i < chosen.size(); ++i) {
    try {
      occ::SolidPieces pieces = solid.split(0, chosen[i]->surface);
      if (pieces.size() >= 2) cut[i] = std::move(pieces);
    } catch (const MeshingError&) {
      // the kernel could not make this cut: try the next
    }
  }
  // Their pieces judged in parallel, kept in the candidates' order; the
  // first error in that order is the one raised.
  std::vector<std::optional<Evaluated>> made(chosen.size());
  std::vector<std::exception_ptr> errors(chosen.size());
  arena_.execute([&] {
    tbb::parallel_for(size_t{0}, chosen.size(), [&](size_t i) {
      if (!cut[i]) return;
      try {
        made[i] = judge(std::move(*cut[i]), *chosen[i], size, registry_, options_.settings);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  });
  std::vector<Evaluated> evaluated;
  for (size_t i = 0; i < chosen.size(); ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    if (!made[i]) continue;
    Evaluated& e = *made[i];
    if (log::threshold() <= log::Level::Info) {
      std::string schemes;
      for (const auto& v : e.verdicts) schemes += " " + (v.ok ? v.scheme : std::string("-"));
      log::info("decompose: depth " + std::to_string(depth) + ", " + e.candidate->through + " (" +
                describe(e.candidate->surface) + "): " + std::to_string(e.outcome.pieces) +
                " pieces," + schemes + ", thinnest " + std::to_string(e.thinnest));
    }
    evaluated.push_back(std::move(e));
  }

  // Cuts whose pieces all have a scheme, best first; the first that plans
  // as a whole (shared faces agree, intervals feasible) wins.
  std::vector<Evaluated*> complete, partial;
  for (Evaluated& e : evaluated) {
    if (e.outcome.failing == 0) {
      e.score = complete_score(e.outcome);
      complete.push_back(&e);
    } else {
      e.score = partial_score(e.outcome);
      partial.push_back(&e);
    }
  }
  const auto by_score = [](const Evaluated* a, const Evaluated* b) {
    return better(a->score, b->score);
  };
  std::stable_sort(complete.begin(), complete.end(), by_score);
  std::stable_sort(partial.begin(), partial.end(), by_score);
  // A piece's cuts are checked among the solids around it: the first of
  // them whose pieces plan alone may conflict with a neighbour where the
  // next one does not.
  for (Evaluated* e : complete) {
    const std::string reason = check_in(e->pieces, &e->model, context);
    if (reason.empty()) {
      return SolidPlan{e->pieces, {applied(*e, depth, e->outcome.thinnest * size)}};
    }
    ++conflicts_;
    log::info("decompose: " + e->candidate->through + " does not plan: " + reason);
    if (conflict_.empty()) {
      conflict_ = "the best cut with sweepable pieces, " + e->candidate->through +
                  in_brief(e->candidate->surface) + ", does not plan: " + reason;
    }
  }
  if (depth == 0 && !partial.empty() && best_partial_.empty()) {
    const Evaluated& e = *partial.front();
    for (size_t k = 0; k < e.verdicts.size(); ++k) {
      if (e.verdicts[k].ok) continue;
      // Cooper's furthest sorting first: the whole of every scheme's
      // refusal would push it past what a line shows.
      best_partial_ =
          "the best, " + e.candidate->through + in_brief(e.candidate->surface) +
          ", leaves a piece of volume " + number(e.model.volumes()[k].volume) +
          " that no scheme meshes: " +
          part_ids_.translate(deciding_reason(e.verdicts[k].why), e.model, static_cast<int>(k) + 1);
      break;
    }
  }
  if (depth + 1 >= options_.max_depth) return std::nullopt;
  // Cut again the pieces the best partial cuts leave, of those that made
  // progress: a cut that leaves no piece sweepable is no nearer an answer
  // than the solid was, and cutting its pieces again multiplies the cuts a
  // refusal tries (occt_bottle: 28 cuts, 19 of them under such cuts).
  std::vector<Evaluated*> progress;
  for (Evaluated* e : partial) {
    if (e->outcome.failing < e->outcome.pieces) progress.push_back(e);
  }
  const int branches = std::min(static_cast<int>(progress.size()), options_.branches);
  for (int b = 0; b < branches; ++b) {
    const Evaluated& e = *progress[static_cast<size_t>(b)];
    SolidPlan plan{e.pieces, {applied(e, depth, e.outcome.thinnest * size)}};
    bool ok = true;
    // Last piece first, so that replacing one by its pieces keeps the
    // indices of those still to do.
    for (int k = e.pieces.size() - 1; k >= 0 && ok; --k) {
      if (e.verdicts[static_cast<size_t>(k)].ok) continue;
      // Piece k's cuts must plan among the pieces settled so far: those
      // with a scheme and those cut already (after k); the pieces before it
      // that still need cuts are left out until their turn.
      const occ::SolidPieces settled = plan.pieces;
      const Evaluated* parent = &e;
      const Context inner = [settled, parent, k, &context](const occ::SolidPieces& sub) {
        occ::SolidPieces all = settled.replace(k, sub);
        for (int j = k - 1; j >= 0; --j) {
          if (!parent->verdicts[static_cast<size_t>(j)].ok) all = all.replace(j, {});
        }
        return context ? context(all) : all;
      };
      auto sub = solve(e.pieces.only(k), depth + 1, candidates, inner);
      if (!sub) {
        ok = false;
        break;
      }
      plan.pieces = plan.pieces.replace(k, sub->pieces);
      plan.cuts.insert(plan.cuts.end(), sub->cuts.begin(), sub->cuts.end());
    }
    if (!ok) continue;
    const std::string reason = check_in(plan.pieces, nullptr, context);
    if (reason.empty()) return plan;
    ++conflicts_;
    log::info("decompose: the cuts of " + e.candidate->through +
              " do not plan together: " + reason);
    if (conflict_.empty()) conflict_ = "the cuts found do not plan together: " + reason;
  }
  return std::nullopt;
}

}  // namespace cooperage::decompose
