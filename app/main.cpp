// The `cooperage` command line: parse arguments, call the library, print.
// Exit codes: 0 success, 1 a quality check failed, 2 bad input (file,
// journal, geometry, no applicable scheme), 3 internal error.
#include "model_report.h"
#include "plan_command.h"
#include "progress.h"
#include "quality_command.h"
#include "run_report.h"
#include "schemes_command.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/build_geometry.h"
#include "framework/pipeline/mesher.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace cooperage;

constexpr int kExitQualityFailed = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;

int run_info(const std::string& file, bool json, bool no_imprint) {
  const geom::Model model = pipeline::load_any(file, !no_imprint);
  if (json) {
    app::write_model_json(model, file, std::cout);
  } else {
    app::write_model_text(model, file, std::cout);
  }
  return 0;
}

// `plugins` (--plugin) load after COOPERAGE_PLUGIN_PATH's and before the journal's.
int finish_run(const io::Job& job, const std::vector<std::string>& plugins, int dim, int threads,
               bool quiet) {
  scheme::Registry registry;
  register_schemes(registry, job.mesh ? builtin_options(*job.mesh) : BuiltinOptions{},
                   run_plugins(plugins, job.plugins));
  app::Progress progress(!quiet);
  pipeline::MeshOptions options;
  options.planner = selector::planner();
  options.dim = dim;
  options.threads = threads;
  options.progress = [&](const std::string& stage, std::size_t done, std::size_t total) {
    progress.update(stage, done, total);
  };
  const pipeline::RunResult result = pipeline::run_job(job, registry, options);
  progress.finish();
  app::write_run_report(result, std::cout);
  return result.quality.failed() ? kExitQualityFailed : 0;
}

int run_journal(const std::string& file, const std::vector<std::string>& plugins,
                const std::string& report, int threads, bool quiet) {
  io::Job job = io::read_journal(file);
  if (!report.empty()) job.reports.push_back({report, {"command line", 0, "--report"}});
  return finish_run(job, plugins, 3, threads, quiet);
}

// `cooperage mesh MODEL --size S -o OUT [--elements hex|wedge|mixed]
// [--report R]`: a journal built on the fly; wedge and mixed apply to every volume.
int run_mesh(const std::string& model, const std::vector<std::string>& plugins, double size,
             int dim, const std::string& output, const std::string& report, bool binary,
             bool no_imprint, io::ElementKind elements, int threads, bool quiet) {
  if (!(size > 0)) throw MeshingError(ErrorCode::InvalidInput, "--size must be positive");
  pipeline::ModelJobOptions options;
  options.size = size;
  options.imprint_merge = !no_imprint;
  options.elements = elements;
  options.exports = {output};
  options.binary = binary;
  if (!report.empty()) options.reports = {report};
  return finish_run(pipeline::model_job(model, options), plugins, dim, threads, quiet);
}

// `cooperage schemes`: the registry of a run without a journal.
int run_schemes(const std::vector<std::string>& plugins, bool json) {
  scheme::Registry registry;
  register_schemes(registry, {}, run_plugins(plugins, {}));
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
  register_schemes(registry, {}, run_plugins(plugins, {}), false);
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
  info->add_option("FILE", info_file, "A CAD file (.step .stp .iges .igs .brep) or a journal (.xml)")
      ->required();
  info->add_flag("--json", info_json, "Print one JSON object instead of text");
  info->add_flag("--no-imprint", info_no_imprint,
                 "Keep touching solids separate (no imprint and merge)");

  std::string run_file, report_file;
  int threads = 0;
  bool quiet = false;
  CLI::App* run = app.add_subcommand("run", "Run a journal: geometry, meshing, quality, exports");
  run->add_option("JOURNAL", run_file, "The journal (.xml)")->required();
  run->add_option("--threads", threads, "Worker threads (0: all cores; same output for any)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("-q,--quiet", quiet, "No progress output");
  run->add_option("--report", report_file,
                  "Also write an HTML report (pictures, quality histograms, plan, times)");

  std::string mesh_file, mesh_output;
  double mesh_size = 0;
  int mesh_dim = 3;
  bool mesh_no_imprint = false;
  bool mesh_binary = false;
  std::string mesh_elements = "hex";
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh a CAD file with automatic schemes, no journal");
  mesh->add_option("MODEL", mesh_file, "A CAD file (.step .stp .iges .igs .brep)")->required();
  mesh->add_option("--size", mesh_size, "Element size, in the model's length unit")->required();
  mesh->add_option("--dim", mesh_dim, "3: volume mesh (default); 2: surface mesh only")
      ->check(CLI::IsMember({2, 3}));
  mesh->add_option("-o,--output", mesh_output, "Output file: .exo .msh .vtu or .inp")->required();
  mesh->add_flag("--binary", mesh_binary, "Binary .vtu (raw appended) or .msh (Gmsh 4.1 binary)");
  mesh->add_flag("--no-imprint", mesh_no_imprint, "Keep touching solids separate");
  mesh->add_option("--elements", mesh_elements,
                   "hex (default); wedge: triangle caps swept into wedges; mixed: quad-dominant "
                   "caps swept into hexes and wedges")
      ->check(CLI::IsMember({"hex", "wedge", "mixed"}));
  mesh->add_option("--threads", threads, "Worker threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  mesh->add_flag("-q,--quiet", quiet, "No progress output");
  mesh->add_option("--report", report_file,
                   "Also write an HTML report (pictures, quality histograms, plan, times)");

  std::string plan_file;
  double plan_size = 0;
  bool plan_json = false;
  CLI::App* plan = app.add_subcommand(
      "plan", "Show the scheme chosen for every volume and surface, and why, without meshing");
  plan->add_option("FILE", plan_file, "A journal (.xml) or a CAD file")->required();
  plan->add_option("--size", plan_size, "Element size (overrides the journal's)")
      ->check(CLI::PositiveNumber);
  plan->add_flag("--json", plan_json, "Print one JSON object instead of text");

  bool schemes_json = false;
  CLI::App* schemes = app.add_subcommand(
      "schemes", "List every registered scheme: name, dimension, origin (built in or which "
                 "plug-in library), the roles it serves");
  schemes->add_flag("--json", schemes_json, "Print one JSON array instead of text");

  std::string quality_file;
  bool quality_json = false;
  CLI::App* quality = app.add_subcommand(
      "quality", "Report the element quality of a mesh file, block by block");
  quality->add_option("FILE", quality_file, "A mesh file (.exo .e .g .msh .vtu)")->required();
  quality->add_flag("--json", quality_json, "Print one JSON object instead of text");
  quality->add_option("--report", report_file,
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

  try {
    if (*schemes) return run_schemes(plugins, schemes_json);
    if (*info) {
      check_plugins(plugins);
      return run_info(info_file, info_json, info_no_imprint);
    }
    if (*run) return run_journal(run_file, plugins, report_file, threads, quiet);
    if (*quality) {
      check_plugins(plugins);
      return app::run_quality(quality_file, quality_json, std::cout, report_file);
    }
    if (*plan) {
      return app::run_plan(plan_file, plan_size > 0 ? std::optional<double>(plan_size) : std::nullopt,
                           plan_json, plugins, std::cout);
    }
    if (*mesh) {
      const io::ElementKind elements = mesh_elements == "wedge"   ? io::ElementKind::Wedge
                                       : mesh_elements == "mixed" ? io::ElementKind::Mixed
                                                                  : io::ElementKind::Hex;
      return run_mesh(mesh_file, plugins, mesh_size, mesh_dim, mesh_output, report_file,
                      mesh_binary, mesh_no_imprint, elements, threads, quiet);
    }
  } catch (const MeshingError& e) {
    std::cerr << "cooperage: error: " << e.what() << '\n';
    return e.code() == ErrorCode::Internal ? kExitInternal : kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cooperage: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
  return 0;
}
