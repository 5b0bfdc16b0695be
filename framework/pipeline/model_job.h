// model_job: the job of a CAD file meshed without a journal, as `cooperage
// mesh MODEL --size S` and Python's cooperage.mesh() run it; plan_input:
// what `cooperage plan FILE` and Python's cooperage.plan() plan.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "framework/decompose/decompose.h"
#include "framework/geometry/model.h"
#include "framework/io/element_size.h"
#include "framework/io/job.h"
#include "framework/pipeline/planner.h"
#include "framework/scheme/registry.h"

namespace cooperage::pipeline {

struct ModelJobOptions {
  io::ElementSize size;                             ///< a length (> 0) or D/N
  bool imprint_merge = true;                        ///< fragment touching solids
  io::ElementKind elements = io::ElementKind::Hex;  ///< for every volume
  std::vector<std::string> exports;                 ///< mesh files to write
  bool binary = false;                              ///< binary .vtu/.msh/.stl/.ply exports
  std::vector<std::string> reports;                 ///< HTML reports to write
  /// Where the settings came from, for error messages: "command line",
  /// "cooperage.mesh()"; each setting's element names its option.
  std::string origin = "command line";
  std::string export_option = "-o";
  std::string report_option = "--report";
  std::string binary_option = "--binary";
  /// Cut volumes no volume scheme applies to (framework/decompose/).
  io::Decompose decompose = io::Decompose::Auto;
  /// Halvings of a failed volume's size (io::MeshSettings::finer_retries).
  int finer_retries = io::MeshSettings{}.finer_retries;
  /// A failing check on the scaled Jacobian, as a journal's <quality
  /// metric="scaled_jacobian" min action="fail">: the run fails below it,
  /// and a volume below it is first meshed again finer (finer_retry.h).
  std::optional<double> min_scaled_jacobian;
  std::string min_scaled_jacobian_option = "--min-scaled-jacobian";
};

/// A job that imports `model` (.step .stp .iges .igs .brep), meshes it at
/// options.size with automatic schemes and writes the exports and reports.
/// The element kind is the mesh's (every volume's, the decomposition's
/// pieces too).
/// @throws MeshingError(InvalidInput) for a size that is not positive, or
///         binary asked of an export that is not .vtu, .msh, .stl or .ply.
io::Job model_job(const std::string& model, const ModelJobOptions& options);

/// What `cooperage plan FILE` (and Python's cooperage.plan()) plans: the
/// model and mesh settings of a journal (.xml), or of a CAD file with the
/// settings `cooperage mesh` would give it.
struct PlanInput {
  geom::Model model;
  io::MeshSettings settings;
  decompose::Report decomposition;         ///< the cuts made (none without a registry)
  std::vector<io::PluginSetting> plugins;  ///< a journal's <plugin> elements
};

/// The options of `cooperage plan` besides the size, each as `cooperage
/// mesh` takes it, so that a plan shows what that mesh command would do.
/// Unset: the default (a CAD file) or the journal's own setting.
struct PlanOverrides {
  std::optional<bool> imprint_merge;        ///< --no-imprint: CAD files only
  std::optional<io::ElementKind> elements;  ///< --elements: over <mesh elements> too
  std::optional<io::Decompose> decompose;   ///< --decompose: over <mesh decompose> too
  std::optional<double> max_elements;       ///< --max-elements: over <mesh max_elements> too
  std::string origin = "command line";      ///< for errors, with the option's name:
  std::string imprint_option = "--no-imprint";
};

/// Reads `file`, builds its model, applies `size` and `overrides` (over the
/// journal's settings), resolves a size "D/N" against the model and checks the settings against the
/// model (check_settings). With a registry and a planner, volumes no volume scheme applies to are
/// decomposed as `cooperage mesh` and `run` do (build_decomposed_geometry); a CAD file is planned
/// with decompose="auto" unless overridden.
/// @throws MeshingError(InvalidInput) for --no-imprint given with a journal
///         (it sets that itself); as read_journal(),
///         build_geometry(), load_any(), build_decomposed_geometry() and
///         check_settings() do.
PlanInput plan_input(const std::string& file, std::optional<io::ElementSize> size,
                     const scheme::Registry* registry = nullptr, const Planner& planner = {},
                     const PlanOverrides& overrides = {});

}  // namespace cooperage::pipeline
