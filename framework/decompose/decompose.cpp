#include "framework/decompose/decompose.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/decompose/piece_verdict.h"
#include "framework/decompose/same_part.h"
#include "framework/decompose/search_cuts.h"

#include <algorithm>
#include <chrono>

namespace cooperage::decompose {
namespace {

/// Volumes with more faces are not searched (see decompose()).
constexpr int kMaxSearchFaces = 80;
/// Candidate cuts x faces per volume: 80 cuts up to 25 faces, fewer above.
constexpr int kSearchFaceCuts = 2000;

}  // namespace

std::vector<RefusedVolume> refused_volumes(const geom::Model& model,
                                           const scheme::Registry& registry,
                                           const scheme::Settings* settings) {
  std::vector<RefusedVolume> out;
  for (const geom::Volume& v : model.volumes()) {
    PieceVerdict verdict = best_scheme(model, v.id, registry, settings);
    if (!verdict.ok) out.push_back({v.id, std::move(verdict.why)});
  }
  return out;
}

std::vector<int> unmeshable_volumes(const geom::Model& model, const scheme::Registry& registry,
                                    const scheme::Settings* settings) {
  std::vector<int> out;
  for (const RefusedVolume& r : refused_volumes(model, registry, settings)) out.push_back(r.volume);
  return out;
}

Decomposed decompose(const occ::SolidPieces& solids, const geom::Model& model,
                     const scheme::Registry& registry, const ModelCheck& check,
                     const DecomposeOptions& options) {
  return decompose(solids, model, registry, check, options,
                   refused_volumes(model, registry, options.settings));
}

Decomposed decompose(const occ::SolidPieces& solids, const geom::Model& model,
                     const scheme::Registry& registry, const ModelCheck& check,
                     const DecomposeOptions& options, const std::vector<RefusedVolume>& refused) {
  if (!(options.size > 0)) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "automatic decomposition needs a positive element size");
  }
  const auto t0 = std::chrono::steady_clock::now();
  Decomposed out;
  const int n = static_cast<int>(model.volumes().size());
  if (solids.size() != n) {
    throw MeshingError(ErrorCode::Internal, "decomposition: " + std::to_string(solids.size()) +
                                                " solids for " + std::to_string(n) + " volumes");
  }
  std::vector<int> origin;  // per solid of `result`: the input volume id
  for (int v = 1; v <= n; ++v) origin.push_back(v);
  occ::SolidPieces result = solids;
  // Volumes in descending id order so that replacing one solid by its pieces
  // keeps the indices of the ones still to do.
  for (auto it = refused.rbegin(); it != refused.rend(); ++it) {
    const int v = it->volume;
    VolumeDecomposition d;
    d.volume = v;
    d.name = model.volume(v).name;
    d.why = it->why;
    d.refusal =
        (options.settings ? *options.settings : scheme::Settings::none()).no_scheme_applies(v);
    const std::string refusal = d.refusal;
    // Each candidate cut costs a boolean and a plan of the pieces, both
    // growing with the faces: the number of cuts tried shrinks with them, and
    // a volume too intricate for cuts through its own faces to help is left
    // to the user (an impeller took minutes and found nothing).
    int faces = 0;
    for (const auto& shell : model.volume(v).shells) faces += static_cast<int>(shell.size());
    if (faces > kMaxSearchFaces) {
      throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(v),
                         refusal +
                             "; automatic decomposition is not tried on a volume of "
                             "more than " +
                             std::to_string(kMaxSearchFaces) + " faces (it has " +
                             std::to_string(faces) + ") (" + d.why + ")",
                         "cut the volume with <webcut> in a journal (`cooperage plan` gives every "
                         "scheme's reason)");
    }
    DecomposeOptions budget = options;
    budget.max_cuts = std::min(options.max_cuts, std::max(8, kSearchFaceCuts / std::max(faces, 1)));
    const PartIds part_ids(model, v);
    CutSearch search(registry, check, budget, part_ids);
    auto plan = search.solve(solids.only(v - 1));
    d.tried = search.tried();
    out.report.tried += d.tried;
    if (!plan) {
      const std::string failure = search.failure();
      // Pieces swept in different directions meet where one's cap is the
      // other's side: triangles against quads in wedges, where mixed
      // elements (quads on such a cap) would fit.
      const bool wedges =
          options.settings && options.settings->elements(v) == io::ElementKind::Wedge;
      const bool tri_on_quads = failure.find("needs tri for") != std::string::npos ||
                                failure.find(" but tri for") != std::string::npos;
      // The details last, in parentheses: the command line puts them on a
      // line of their own.
      throw MeshingError(
          ErrorCode::NotApplicable, EntityRef::volume(v),
          refusal + "; automatic decomposition " + failure + " (" + d.why + ")",
          wedges && tri_on_quads
              ? "the pieces a cut leaves meet with a triangle cap on a quad side, which "
                "wedges cannot join; elements \"mixed\" (--elements mixed) meshes such pieces"
              : "`cooperage plan` gives every scheme's reason; cut the volume with "
                "<webcut> or give it a sweep hint (<volume sources/targets/direction>)");
    }
    d.cuts = plan->cuts;
    result = result.replace(v - 1, plan->pieces);
    origin.erase(origin.begin() + (v - 1));
    origin.insert(origin.begin() + (v - 1), static_cast<size_t>(plan->pieces.size()), v);
    out.report.volumes.insert(out.report.volumes.begin(), std::move(d));
  }
  if (refused.empty()) {
    out.model = model;
  } else {
    // Glued, as the trial models were (the solids only touch), unless that
    // changed the part's skin or volume: a face pair the glue left unmerged
    // would add twice its area to the skin; then fused in full. gmsh_as1-tu-203:
    // 0.9 s of 4.8 (a fuse of 21 solids), the same model.
    out.model = result.build_model(true, true);
    if (!same_skin_and_volume(out.model, model)) {
      log::info("decompose: the glued pieces differ from the part; fusing them in full");
      out.model = result.build_model(true);
    }
    if (static_cast<int>(out.model.volumes().size()) != result.size()) {
      throw MeshingError(ErrorCode::GeometryError,
                         "decomposition: imprinting the pieces changed their number (" +
                             std::to_string(result.size()) + " pieces, " +
                             std::to_string(out.model.volumes().size()) + " volumes)");
    }
  }
  out.report.origin = origin;
  for (VolumeDecomposition& d : out.report.volumes) {
    for (size_t k = 0; k < origin.size(); ++k) {
      if (origin[k] == d.volume) d.pieces.push_back(static_cast<int>(k) + 1);
    }
  }
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cooperage::decompose
