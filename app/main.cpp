// The `cooperage` command line: parse arguments, call the library, print.
// Exit codes: 0 success, 1 a quality check failed, 2 bad input (file,
// journal, geometry, no applicable scheme), 3 internal error.
#include "huge_pages.h"
#include "model_report.h"
#include "plan_command.h"
#include "progress.h"
#include "quality_command.h"
#include "run_report.h"
#include "schemes_command.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/core/text.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/element_size.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace cooperage;

constexpr int kExitQualityFailed = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;
/// An error line longer than this is cut: a sentence, not a listing of
/// every face (issue 16 item 5).
constexpr std::size_t kMaxErrorLine = 240;

int run_info(const std::string& file, bool json, bool no_imprint) {
  const geom::Model model = pipeline::load_any(file, !no_imprint);
  if (json) {
    app::write_model_json(model, file, std::cout);
  } else {
    app::write_model_text(model, file, std::cout);
  }
  return 0;
}

/// Options of `run` and `mesh` that limit or relax a run.
struct RunLimits {
  int threads = 0;
  bool quiet = false;
  double max_elements = 0;      ///< 0: the journal's or the default
  double volume_tolerance = 0;  ///< percent; 0: the journal's or the default
  bool allow_partial = false;
  /// --plugin libraries; they load after COOPERAGE_PLUGIN_PATH's and before
  /// the journal's.
  std::vector<std::string> plugins;
};

/// An error in at most three lines (issue 16 item 5): the entity and the
/// reason; the details of a long reason ("no hex scheme applies (map: ...;
/// cooper: ...)") on a second line, cut; what to do on the last.
void print_error(const MeshingError& e) {
  std::string first = e.what();
  std::string details;
  // The parenthesis that closes the message, matched backwards, holds its
  // details; they go to a line of their own when long (a list of every
  // scheme's reason), and stay when short, however long the file name.
  if (!first.empty() && first.back() == ')') {
    int depth = 0;
    std::size_t open = std::string::npos;
    for (std::size_t i = first.size(); i-- > 0;) {
      if (first[i] == ')') ++depth;
      if (first[i] == '(' && --depth == 0) {
        open = i;
        break;
      }
    }
    if (open != std::string::npos && open > 0 && first[open - 1] == ' ' &&
        first.size() - open > 60) {
      details = first.substr(open + 1, first.size() - open - 2);
      first.resize(open - 1);
    }
  }
  std::cerr << "cooperage: error: " << clip(first, kMaxErrorLine) << '\n';
  if (!details.empty()) std::cerr << "  " << clip(details, kMaxErrorLine) << '\n';
  if (!e.hint().empty()) std::cerr << "  " << clip(e.hint(), kMaxErrorLine) << '\n';
}

int finish_run(const io::Job& job, int dim, const RunLimits& limits) {
  scheme::Registry registry;
  register_schemes(registry, run_plugins(limits.plugins, job.plugins));
  app::Progress progress(!limits.quiet);
  pipeline::MeshOptions options;
  options.planner = selector::planner();
  options.dim = dim;
  options.threads = limits.threads;
  if (limits.max_elements > 0) options.max_elements = limits.max_elements;
  if (limits.volume_tolerance > 0) options.volume_tolerance = limits.volume_tolerance / 100.0;
  options.allow_partial = limits.allow_partial;
  options.progress = [&](const std::string& stage, std::size_t done, std::size_t total) {
    progress.update(stage, done, total);
  };
  options.after_geometry = [threads = limits.threads] {
    app::share_heap_when_few_threads(threads);
  };
  try {
    const pipeline::RunResult result = pipeline::run_job(job, registry, options);
    progress.finish();
    if (job.mesh && job.mesh->size_divisor && result.size) {
      std::cout << "size D/" << number_text(*job.mesh->size_divisor) << " = "
                << number_text(*result.size) << '\n';
    }
    app::write_run_report(result, std::cout);
    return result.failed() ? kExitQualityFailed : 0;
  } catch (const pipeline::IncompleteMesh& e) {
    progress.finish();
    app::write_verdicts(e.verdicts(), std::cout, e.origin());
    // The error line names the volume as the lines above do.
    const std::string name = app::entity_name(e.entity(), e.origin());
    if (name != e.entity().name())
      throw MeshingError(e.code(), EntityRef::none(), name + ": " + e.message(), e.hint());
    throw;
  }
}

int run_journal(const std::string& file, const std::string& report, const RunLimits& limits) {
  io::Job job = io::read_journal(file);
  if (!report.empty()) job.reports.push_back({report, {"command line", 0, "--report"}});
  return finish_run(job, 3, limits);
}

/// The element kind a `--elements` value names (checked by the parser).
io::ElementKind element_kind(const std::string& name) {
  return name == "wedge"   ? io::ElementKind::Wedge
         : name == "mixed" ? io::ElementKind::Mixed
                           : io::ElementKind::Hex;
}

io::Decompose decompose_mode(const std::string& name) {
  return name == "off" ? io::Decompose::Off : io::Decompose::Auto;
}

// `cooperage mesh MODEL --size S -o OUT [--elements hex|wedge|mixed]
// [--report R]`: a journal built on the fly; wedge and mixed apply to every volume.
// --size: a length, or D/N (the model's bounding-box diagonal over N).
io::ElementSize element_size(const std::string& text) {
  const std::optional<io::ElementSize> size = io::parse_element_size(text);
  if (!size) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "--size must be a positive length or D/N (the model's bounding-box "
                       "diagonal over N, e.g. D/40), got \"" +
                           clip(text, 40) + "\"");
  }
  return *size;
}

int run_mesh(const std::string& model, const io::ElementSize& size, int dim,
             const std::string& output, const std::string& report, bool binary, bool no_imprint,
             io::ElementKind elements, const RunLimits& limits, io::Decompose decompose,
             int finer_retries, std::optional<double> min_scaled_jacobian) {
  pipeline::ModelJobOptions options;
  options.decompose = decompose;
  options.finer_retries = finer_retries;
  options.size = size;
  options.imprint_merge = !no_imprint;
  options.elements = elements;
  options.exports = {output};
  options.binary = binary;
  if (!report.empty()) options.reports = {report};
  options.min_scaled_jacobian = min_scaled_jacobian;
  return finish_run(pipeline::model_job(model, options), dim, limits);
}

// `cooperage schemes`: the registry of a run without a journal.
int run_schemes(const std::vector<std::string>& plugins, bool json) {
  scheme::Registry registry;
  register_schemes(registry, run_plugins(plugins, {}));
  if (json) {
    app::write_schemes_json(registry, std::cout);
  } else {
    app::write_schemes_text(registry, std::cout);
  }
  return 0;
}

// info and quality use no scheme; a --plugin given to them is still loaded,
// so a broken one is reported the same way everywhere.
void check_plugins(const std::vector<std::string>& plugins) {
  if (plugins.empty()) return;
  scheme::Registry registry;
  register_schemes(registry, run_plugins(plugins, {}), false);
}

}  // namespace

int main(int argc, char** argv) {
  occ::silence_kernel_output();
  CLI::App app{"Cooperage: all-hexahedral meshing of CAD solids by sweeping (the cooper tool)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cooperage 0.1.0");
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Print diagnostics on stderr");
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins,
                 "Load a plug-in library of schemes (repeatable; before or after the "
                 "subcommand; COOPERAGE_PLUGIN_PATH lists more)")
      ->allow_extra_args(false);
  // --plugin and -v may follow the subcommand too.
  app.fallthrough();

  std::string info_file;
  bool info_json = false;
  bool info_no_imprint = false;
  CLI::App* info = app.add_subcommand(
      "info", "Describe a model: volumes, surfaces, curves, vertices, types, measures");
  info->add_option("FILE", info_file,
                   "A CAD file (.step .stp .iges .igs .brep) or a journal (.xml)")
      ->required();
  info->add_flag("--json", info_json, "Print one JSON object instead of text");
  info->add_flag("--no-imprint", info_no_imprint,
                 "Keep touching solids separate (no imprint and merge)");

  std::string run_file, report_file;
  RunLimits limits;
  auto add_limits = [&](CLI::App* cmd) {
    cmd->add_option("--threads", limits.threads,
                    "Worker threads (0: all cores; at most the hardware's; same output for any)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("-q,--quiet", limits.quiet, "No progress output");
    cmd->add_option("--max-elements", limits.max_elements,
                    "Refuse a mesh estimated above this many elements (default 2e8, at most 1e9)")
        ->check(CLI::Range(1.0, 1e9));
    cmd->add_option("--volume-tolerance", limits.volume_tolerance,
                    "Fail when a meshed volume (area) deviates from the CAD's by more than this "
                    "many percent (default 1); round faces are sized to lose at most half "
                    "of it")
        ->check(CLI::Range(1e-6, 100.0));
    cmd->add_flag("--allow-partial", limits.allow_partial,
                  "Write the volumes that meshed when others cannot be meshed (exit code 1)");
    cmd->add_option("--report", report_file,
                    "Also write an HTML report (pictures, quality histograms, plan, times)");
  };
  CLI::App* run = app.add_subcommand("run", "Run a journal: geometry, meshing, quality, exports");
  run->add_option("JOURNAL", run_file, "The journal (.xml)")->required();
  add_limits(run);

  std::string mesh_file, mesh_output;
  std::string mesh_size;
  int mesh_dim = 3;
  bool mesh_no_imprint = false;
  bool mesh_binary = false;
  std::string mesh_elements = "hex";
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh a CAD file with automatic schemes, no journal");
  mesh->add_option("MODEL", mesh_file, "A CAD file (.step .stp .iges .igs .brep)")->required();
  mesh->add_option("--size", mesh_size,
                   "Element size: a length in the model's unit, or D/N (the bounding-box "
                   "diagonal over N, e.g. D/40)")
      ->required();
  mesh->add_option("--dim", mesh_dim, "3: volume mesh (default); 2: surface mesh only")
      ->check(CLI::IsMember({2, 3}));
  mesh->add_option(
          "-o,--output", mesh_output,
          "Output file: .exo .msh .vtu .inp, or a surface format .obj .off .stl .ply (a 3D mesh "
          "gives its boundary)")
      ->required();
  mesh->add_flag("--binary", mesh_binary,
                 "Binary .vtu (raw appended), .msh (Gmsh 4.1 binary), .stl or .ply");
  mesh->add_flag("--no-imprint", mesh_no_imprint, "Keep touching solids separate");
  mesh->add_option("--elements", mesh_elements,
                   "hex (default); wedge: triangle caps swept into wedges; mixed: quad-dominant "
                   "caps swept into hexes and wedges")
      ->check(CLI::IsMember({"hex", "wedge", "mixed"}));
  add_limits(mesh);
  std::string mesh_decompose = "auto";
  mesh->add_option("--decompose", mesh_decompose,
                   "auto (default): cut volumes no scheme applies to into sweepable pieces; "
                   "off: refuse them")
      ->check(CLI::IsMember({"auto", "off"}));
  int mesh_finer_retries = io::MeshSettings{}.finer_retries;
  mesh->add_option("--finer-retries", mesh_finer_retries,
                   "A volume its scheme fails on after planning is meshed again at half its size, "
                   "at most this many times, then (a straight sweep) swept the other way, from its "
                   "size down; a straight sweep meshed below a scaled Jacobian of 0.2 is tried the "
                   "other way too, kept when better (default 2; 0: never)")
      ->check(CLI::Range(0, io::MeshSettings::kMaxFinerRetries));
  std::optional<double> mesh_min_sj;
  mesh->add_option("--min-scaled-jacobian", mesh_min_sj,
                   "Fail (exit 1, no file) when an element's scaled Jacobian is below this; a "
                   "volume below it is first meshed again at half its size (--finer-retries "
                   "times at most)")
      ->check(CLI::Range(-1.0, 1.0));

  std::string plan_file;
  std::optional<std::string> plan_size;
  bool plan_json = false;
  CLI::App* plan = app.add_subcommand(
      "plan", "Show the scheme chosen for every volume and surface, and why, without meshing");
  plan->add_option("FILE", plan_file, "A journal (.xml) or a CAD file")->required();
  plan->add_option("--size", plan_size,
                   "Element size, a length or D/N as for mesh (overrides the journal's)");
  plan->add_flag("--json", plan_json, "Print one JSON object instead of text");
  int plan_dim = 3;
  plan->add_option("--dim", plan_dim,
                   "3: volumes and surfaces (default); 2: surfaces only, as `mesh --dim 2` plans")
      ->check(CLI::IsMember({2, 3}));
  // The options of `mesh` that change the plan, so that a plan shows what
  // that command would do.
  bool plan_no_imprint = false;
  plan->add_flag("--no-imprint", plan_no_imprint,
                 "Keep touching solids separate, as `mesh --no-imprint` (a CAD file)");
  std::optional<double> plan_max_elements;
  plan->add_option("--max-elements", plan_max_elements,
                   "Refuse a size whose mesh is estimated above this many elements, as `mesh` "
                   "does (default 2e8, at most 1e9)")
      ->check(CLI::Range(1.0, 1e9));
  std::optional<std::string> plan_elements, plan_decompose;
  plan->add_option("--elements", plan_elements,
                   "hex (default), wedge or mixed, as `mesh --elements`; overrides a journal's "
                   "<mesh elements>")
      ->check(CLI::IsMember({"hex", "wedge", "mixed"}));
  plan->add_option("--decompose", plan_decompose,
                   "auto (default for a CAD file) or off, as `mesh --decompose`; overrides a "
                   "journal's <mesh decompose>")
      ->check(CLI::IsMember({"auto", "off"}));

  bool schemes_json = false;
  CLI::App* schemes =
      app.add_subcommand("schemes",
                         "List every registered scheme: name, dimension, origin (built in or which "
                         "plug-in library), the roles it serves");
  schemes->add_flag("--json", schemes_json, "Print one JSON array instead of text");

  std::string quality_file;
  bool quality_json = false;
  CLI::App* quality =
      app.add_subcommand("quality", "Report the element quality of a mesh file, block by block");
  quality->add_option("FILE", quality_file, "A mesh file (.exo .e .g .msh .vtu)")->required();
  quality->add_flag("--json", quality_json, "Print one JSON object instead of text");
  quality->add_option(
      "--report", report_file,
      "Also write an HTML report (pictures coloured by scaled Jacobian, histograms)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  log::set_threshold(verbose ? log::Level::Info : log::Level::Warning);
  log::set_sink([](log::Level level, const std::string& line) {
    std::cerr << (level >= log::Level::Warning ? "cooperage: " : "") << line << '\n';
  });

  limits.plugins = plugins;
  try {
    if (*schemes) return run_schemes(limits.plugins, schemes_json);
    if (*info) {
      check_plugins(limits.plugins);
      return run_info(info_file, info_json, info_no_imprint);
    }
    if (*run) return run_journal(run_file, report_file, limits);
    if (*quality) {
      check_plugins(limits.plugins);
      return app::run_quality(quality_file, quality_json, std::cout, report_file);
    }
    if (*plan) {
      pipeline::PlanOverrides overrides;
      if (plan_no_imprint) overrides.imprint_merge = false;
      if (plan_elements) overrides.elements = element_kind(*plan_elements);
      if (plan_decompose) overrides.decompose = decompose_mode(*plan_decompose);
      overrides.max_elements = plan_max_elements;
      std::optional<io::ElementSize> size;
      if (plan_size) size = element_size(*plan_size);
      return app::run_plan(plan_file, size, plan_json, plugins, std::cout, plan_dim, overrides);
    }
    if (*mesh) {
      return run_mesh(mesh_file, element_size(mesh_size), mesh_dim, mesh_output, report_file,
                      mesh_binary, mesh_no_imprint, element_kind(mesh_elements), limits,
                      decompose_mode(mesh_decompose), mesh_finer_retries, mesh_min_sj);
    }
  } catch (const MeshingError& e) {
    print_error(e);
    return e.code() == ErrorCode::Internal ? kExitInternal : kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "cooperage: error: out of memory; use a larger element size or --max-elements\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cooperage: internal error: " << clip(e.what(), kMaxErrorLine) << '\n';
    return kExitInternal;
  }
  return 0;
}
