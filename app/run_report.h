// The per-volume summary table and quality report printed after a run.
#pragma once

#include "framework/pipeline/mesher.h"

#include <ostream>
#include <string>
#include <vector>

namespace cooperage::app {

/// Table: entity, scheme, elements, min / mean scaled Jacobian, time; then
/// the verdict of every volume of an assembly, the journal's quality
/// checks, warnings and the files written.
void write_run_report(const pipeline::RunResult& result, std::ostream& out);

/// One line per volume (surface, for surface meshes): "volume 2: meshed",
/// "volume 3: refused: <reason>", "volume 4: deviates: <reason>". After
/// the automatic decomposition (`origin` not empty: entry k - 1 the input
/// volume of volume k), a volume whose id differs from its input volume's
/// says which it was: "volume 12 (input volume 11): refused: ...".
void write_verdicts(const std::vector<pipeline::Verdict>& verdicts, std::ostream& out,
                    const std::vector<int>& origin = {});

/// "volume 12", or "volume 12 (input volume 11)" when `origin` (entry
/// k - 1 the input volume of volume k) says the decomposition renumbered it.
std::string entity_name(const EntityRef& entity, const std::vector<int>& origin);

}  // namespace cooperage::app
