// Executes a journal's geometry operations on the CAD backend and returns the
// model (first stage of the data flow in docs/design.md).
#pragma once

#include "framework/geometry/model.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/job.h"

#include <string>

namespace cooperage::pipeline {

/// Runs job.geometry in order, then builds the model (imprinted and merged
/// unless job.imprint_merge is false). Relative import paths are resolved
/// against job.base_dir. Throws MeshingError naming the journal line of the
/// failing operation.
geom::Model build_geometry(const io::Job& job);

/// "job.xml:12: <export>: " for a journal element, "" for a step made on
/// the command line (line 0): `cooperage mesh part.step` errors name the
/// file, not a journal that does not exist.
std::string where_prefix(const io::SourceLocation& where);
/// Runs job.geometry in order on `bench` (build_geometry() without the
/// model), for callers that go on working on the shapes (decomposition).
/// `will_mesh`: the interval solver is loaded while an import's child reads.
void run_geometry(const io::Job& job, occ::Workbench& bench, bool will_mesh = false);

/// Reads a model from a CAD file (.step/.stp/.iges/.igs/.brep) or a journal
/// (.xml, geometry only).
geom::Model load_any(const std::string& path, bool imprint_merge = true);

/// Resolves a path written in a journal against the journal's directory.
std::string resolve_path(const std::string& base_dir, const std::string& path);

}  // namespace cooperage::pipeline
