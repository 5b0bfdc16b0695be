// The one-call C++ API, installed as <cooperage/cooperage.h>:
//
//   #include <cooperage/cooperage.h>
//   const cooperage::Result r = cooperage::mesh_file("part.step", 2.0);
//   r.mesh.hex_count();  r.quality.blocks[0].find("scaled_jacobian")->min;
//
// mesh_file() does what `cooperage mesh` does (import, imprint and merge,
// the selector's automatic schemes, interval assignment, meshing, quality)
// and run_journal() what `cooperage run` does. (Not `cooperage::mesh()`:
// that name is the namespace of the mesh types, cooperage::mesh::MeshDB.)
// Everything underneath is installed too (framework/, schemes/, selector/
// under the same prefix) for programs that drive the stages themselves
// (framework/pipeline/mesher.h).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/mesh/mesh_db.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/quality_report.h"
#include "framework/pipeline/scheme_plan.h"

#include <optional>
#include <string>
#include <vector>

namespace cooperage {

/// How mesh_file() and run_journal() mesh.
struct Options {
  int dim = 3;  ///< 3: volume mesh; 2: surface mesh only (mesh_file() only)
  io::ElementKind elements = io::ElementKind::Hex;  ///< every volume's (mesh_file() only)
  int threads = 0;            ///< 0: all cores; the mesh does not depend on it
  bool imprint_merge = true;  ///< touching solids share nodes (mesh_file() only)
  /// Cut volumes no volume scheme applies to into pieces that one does
  /// (mesh_file() only; a journal says so in <mesh decompose>).
  io::Decompose decompose = io::Decompose::Auto;
  /// A volume its scheme accepted and then failed on is meshed again at
  /// half its size, at most this many times, 0 to 4 (mesh_file() only; a
  /// journal says so in <mesh finer_retries>). Each shows as a warning.
  int finer_retries = io::MeshSettings{}.finer_retries;
  /// Fail (no exports; Result::quality.failed()) when an element's scaled
  /// Jacobian is below it, -1 to 1; a volume below it is first meshed again
  /// at half its size, at most finer_retries times, with a warning
  /// (mesh_file() only; a journal says so in <quality>).
  std::optional<double> min_scaled_jacobian;
  /// Mesh files to write (.exo .msh .vtu .inp .obj .off .stl .ply), each
  /// atomically; none are written when meshing fails. run_journal() adds
  /// them to the journal's.
  std::vector<std::string> exports;
  /// Plug-in libraries of schemes to load (framework/scheme/plugin.h), after
  /// those of COOPERAGE_PLUGIN_PATH and before a journal's <plugin>s.
  std::vector<std::string> plugins;
  /// Named element blocks, side sets and node sets for the exports, as a
  /// journal's <block>, <sideset>, <nodeset> (docs/journal.md): ids, names
  /// and entity ids (as `cooperage info` prints them) are checked the same
  /// way; an empty name gets the default ("block_<id>", ...). mesh_file()
  /// only: a journal names its own.
  io::GroupSettings groups;
};

/// A meshed model and its quality report.
struct Result {
  geom::Model model;                        ///< the CAD model as meshed (ids as `cooperage info`)
  mesh::MeshDB mesh;                        ///< nodes, per-entity elements
  pipeline::QualityReport quality;          ///< per block: scaled Jacobian, checked metrics
  pipeline::SchemePlan plan;                ///< the scheme of every volume and surface, and why
  decompose::Report decomposition;  ///< the automatic cuts made (none when none were needed)
  std::vector<pipeline::Warning> warnings;  ///< what schemes gave up, per entity
  std::vector<std::string> written;         ///< files written
  std::vector<pipeline::StageTime> stages;  ///< wall-clock time per stage
};

/// Meshes a CAD file (.step .stp .iges .igs .brep) at element size `size`
/// (model units) with automatic schemes.
/// @throws MeshingError naming the file or entity and the reason (bad file,
///         size not positive, no applicable scheme, a failed scheme).
Result mesh_file(const std::string& path, double size, const Options& options = {});

/// Runs a journal (.xml; docs/journal.md): geometry, meshing, quality checks
/// and exports. A failed check with action="fail" shows in
/// Result::quality.failed() and stops the exports; it does not throw.
/// @throws MeshingError as mesh_file() does, and naming the journal line.
Result run_journal(const std::string& journal, const Options& options = {});

}  // namespace cooperage
