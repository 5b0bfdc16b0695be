// The HTML report of a mesh (issue 18): one self-contained file (no network,
// no external scripts or fonts) with a picture of each part coloured by
// scaled Jacobian (an inline canvas viewer that rotates), the worst elements
// marked, the plan, per-block quality histograms (SVG), element counts, time
// per stage and warnings. Shared by `cooperage mesh/run/quality --report`,
// the journal's <report> and Python's Mesh.report().
#pragma once

#include <string>

#include "framework/report/report_input.h"

namespace cooperage::report {

/// The report as one HTML document. Deterministic for a given input.
/// @param[in] input    the mesh and what to say about it (coords required
///                     when there are blocks)
/// @param[in] options  the face budget of the pictures
/// @throws MeshingError(InvalidInput) for a block whose node indices are
///         out of range or whose stride is too small (from quality::evaluate).
std::string render_report(const ReportInput& input, const ReportOptions& options = {});

/// Renders the report and writes it to `path` atomically: a temporary file in
/// the same directory, renamed on success; on any failure the temporary file
/// is removed and an existing `path` is left as it was.
/// @throws MeshingError(FileNotFound) for an unwritable path, and the errors
///         of render_report() (before any file is created).
void write_report(const std::string& path, const ReportInput& input,
                  const ReportOptions& options = {});

}  // namespace cooperage::report
