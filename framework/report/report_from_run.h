// The report of a meshing run (cooperage mesh/run, Python's Mesh.report).
#pragma once

#include <string>

#include "framework/pipeline/mesher.h"
#include "framework/report/report_input.h"

namespace cooperage::report {

/// What the report shows of a run: one block per volume and element type
/// (a picture per volume), or, for a surface mesh, per surface and type (one
/// picture of all surfaces, quality signed against the CAD normal as in the
/// run's report); the plan, time per stage, warnings, checks and files.
/// The result points into `run`, which must outlive it.
/// @param[in] run    the run (pipeline::run_job)
/// @param[in] title  what was meshed, e.g. the CAD or journal file name
ReportInput report_input(const pipeline::RunResult& run, const std::string& title);

}  // namespace cooperage::report
