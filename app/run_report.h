// The per-volume summary table and quality report printed after a run.
#pragma once

#include "framework/pipeline/mesher.h"

#include <ostream>

namespace cooperage::app {

/// Table: entity, scheme, elements, min / mean scaled Jacobian, time; then
/// the journal's quality checks and the files written.
void write_run_report(const pipeline::RunResult& result, std::ostream& out);

}  // namespace cooperage::app
