// The `cooperage` command line: parse arguments, call the library, print.
// Exit codes: 0 success, 2 bad input (file, journal, geometry), 3 internal error.
#include "model_report.h"

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/pipeline/build_geometry.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;

int run_info(const std::string& file, bool json, bool no_imprint) {
  const cooperage::geom::Model model = cooperage::pipeline::load_any(file, !no_imprint);
  if (json) {
    cooperage::app::write_model_json(model, file, std::cout);
  } else {
    cooperage::app::write_model_text(model, file, std::cout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cooperage: all-hexahedral meshing of CAD solids by sweeping (the cooper tool)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cooperage 0.1.0");
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Print progress and diagnostics on stderr");

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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  cooperage::log::set_threshold(verbose ? cooperage::log::Level::Info
                                        : cooperage::log::Level::Warning);
  cooperage::log::set_sink([](cooperage::log::Level level, const std::string& line) {
    std::cerr << (level >= cooperage::log::Level::Warning ? "cooperage: " : "") << line << '\n';
  });

  try {
    if (*info) return run_info(info_file, info_json, info_no_imprint);
  } catch (const cooperage::MeshingError& e) {
    std::cerr << "cooperage: error: " << e.what() << '\n';
    return e.code() == cooperage::ErrorCode::Internal ? kExitInternal : kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cooperage: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
  return 0;
}
