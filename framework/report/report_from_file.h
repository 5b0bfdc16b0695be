// The report of an existing mesh file (cooperage quality FILE --report).
#pragma once

#include <string>

#include "framework/io/read/read_mesh_file.h"
#include "framework/report/report_input.h"

namespace cooperage::report {

/// One block per block of the file. When the file has volume blocks, each
/// is drawn in its own picture (surface blocks, e.g. side sets, are only
/// measured); otherwise all surface blocks share one picture. Surface
/// elements are measured against their own normal (a file has no CAD).
/// Skipped cell types become notes. The result points into `file`.
/// @param[in] file   the mesh (io::read_mesh_file)
/// @param[in] title  the file name
ReportInput report_input(const io::MeshFile& file, const std::string& title);

}  // namespace cooperage::report
