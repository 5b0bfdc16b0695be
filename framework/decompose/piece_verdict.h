// What the volume schemes say of one volume a priori (applicable() through
// the registry, never a scheme's internals), reduced to the best choice: the
// decomposition's test of whether a piece needs no further cut.
#pragma once

#include "framework/geometry/model.h"
#include "framework/scheme/registry.h"

#include <string>

namespace cooperage::decompose {

struct PieceVerdict {
  bool ok = false;
  std::string scheme;  ///< best applicable scheme (ok only)
  double score = 0.0;  ///< its a-priori score (ok only)
  /// Every scheme's refusal when none applies ("map: ...; cooper: ...").
  std::string why;
};

/// The applicable volume scheme with the best score (ties: registry order),
/// for the job's `settings` (null: defaults, as for the pieces of a cut,
/// which no per-entity setting names). In wedge or mixed elements only the
/// schemes that make wedges count, as in the selector.
PieceVerdict best_scheme(const geom::Model& model, int volume, const scheme::Registry& registry,
                         const scheme::Settings* settings = nullptr);

/// The clause of a refusal a person acts on: cooper's furthest sorting
/// ("along (0, 1, 0): surface 39 cannot be a side (it has 2 loops; ...)")
/// when `why` reports one, else `why` whole.
std::string deciding_reason(const std::string& why);

}  // namespace cooperage::decompose
