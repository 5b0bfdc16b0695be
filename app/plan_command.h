// `cooperage plan`: the selector's choice for every volume and surface, with
// every scheme's verdict and the reason, without meshing; for a volume swept
// by cooper, its barrel tree (barrels, their sides, upper and lower caps --
// real caps and who meshes them, virtual caps and the barrel on their other
// side -- and the imprint operation each barrel needs).
#pragma once

#include "framework/pipeline/model_job.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace cooperage::app {

/// Plans the model of FILE (a journal, or a CAD file with automatic schemes).
/// `size` overrides the journal's global size; without any size the interval
/// feasibility check is skipped (and said so). `plugins` (--plugin) are
/// loaded before the journal's. `dim` 2 plans the surfaces alone, as a
/// surface mesh (`mesh --dim 2`) does: no volume, no decomposition.
/// `overrides` are the options of `mesh` that change the plan. Returns
/// the exit code: 2 when a volume is refused (listed with every scheme's
/// reason, and named on stderr), else 0.
int run_plan(const std::string& file, std::optional<io::ElementSize> size, bool json,
             const std::vector<std::string>& plugins, std::ostream& out, int dim = 3,
             const pipeline::PlanOverrides& overrides = {});

}  // namespace cooperage::app
