// The extension module cooperage._core (pybind11): cooperage.mesh(),
// cooperage.run(), cooperage.plan(), the Mesh class and the exceptions.
// The GIL is released while meshing, planning and writing files.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <functional>

#include "errors.h"
#include "framework/core/text.h"
#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/io/journal_reader.h"
#include "framework/pipeline/model_job.h"
#include "mesh_object.h"
#include "option_values.h"
#include "plan_dicts.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

namespace py = pybind11;

namespace cooperage::python {
namespace {

// Runs a job with the built-in schemes and the selector, without the GIL.
std::shared_ptr<MeshObject> run_job(const std::function<io::Job()>& make_job, int dim, int threads,
                                    const std::string& title) {
  if (threads < 0) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "threads must be 0 (all cores) or positive, got " + std::to_string(threads));
  }
  auto result = std::make_shared<MeshObject>();
  result->title = title;
  py::gil_scoped_release release;
  const io::Job job = make_job();
  scheme::Registry registry;
  register_schemes(registry, job.plugins);
  result->run = pipeline::run_job(job, registry, selector::mesh_options(dim, threads));
  result->groups = job.groups;
  return result;
}

std::shared_ptr<MeshObject> mesh(const std::filesystem::path& model,
                                 const std::variant<double, std::string>& size, int dim,
                                 const std::string& elements, int threads, bool imprint,
                                 int finer_retries, const std::string& decompose,
                                 std::optional<double> min_scaled_jacobian) {
  if (dim != 2 && dim != 3) {
    throw MeshingError(
        ErrorCode::InvalidInput,
        "cooperage.mesh(): dim must be 3 (volumes) or 2 (surfaces), got " + std::to_string(dim));
  }
  if (lower_extension(model.string()) == ".xml") {
    throw MeshingError(ErrorCode::InvalidInput,
                       model.string() +
                           ": cooperage.mesh() takes a CAD file (.step .stp .iges "
                           ".igs .brep); run a journal with cooperage.run()");
  }
  if (finer_retries < 0 || finer_retries > io::MeshSettings::kMaxFinerRetries) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "cooperage.mesh(): finer_retries must be 0 to " +
                           std::to_string(io::MeshSettings::kMaxFinerRetries) + ", got " +
                           std::to_string(finer_retries));
  }
  if (decompose != "auto" && decompose != "off") {
    throw MeshingError(
        ErrorCode::InvalidInput,
        "cooperage.mesh(): decompose must be \"auto\" or \"off\", got \"" + decompose + "\"");
  }
  pipeline::ModelJobOptions options;
  options.size = element_size(size, "cooperage.mesh()");
  options.finer_retries = finer_retries;
  options.decompose = decompose_mode(decompose, "cooperage.mesh()");
  options.imprint_merge = imprint;
  options.elements = element_kind(elements, "cooperage.mesh()");
  options.origin = "cooperage.mesh()";
  options.min_scaled_jacobian = min_scaled_jacobian;
  options.min_scaled_jacobian_option = "min_scaled_jacobian";
  const std::string path = model.string();
  return run_job([&] { return pipeline::model_job(path, options); }, dim, threads, path);
}

std::shared_ptr<MeshObject> run(const std::filesystem::path& journal, int threads) {
  const std::string path = journal.string();
  return run_job([&] { return io::read_journal(path); }, 3, threads, path);
}

}  // namespace
}  // namespace cooperage::python

PYBIND11_MODULE(_core, m) {
  using namespace cooperage::python;
  cooperage::occ::silence_kernel_output();
  m.doc() =
      "Cooperage: all-hexahedral meshing of CAD solids (the compiled core; use the "
      "cooperage package).";
  m.attr("__version__") = COOPERAGE_VERSION;
  register_errors(m);
  bind_mesh(m);
  m.def("mesh", &mesh, py::arg("model"), py::arg("size"), py::arg("dim") = 3,
        py::arg("elements") = "hex", py::arg("threads") = 0, py::arg("imprint") = true,
        py::arg("finer_retries") = cooperage::io::MeshSettings{}.finer_retries,
        py::arg("decompose") = "auto", py::arg("min_scaled_jacobian") = py::none(),
        R"doc(Meshes a CAD file with automatic schemes, as `cooperage mesh` does.

model: a .step/.stp/.iges/.igs/.brep path; size: element size in the model's
units, or "D/N" for the bounding-box diagonal over N (e.g. "D/40"); dim: 3 volume mesh, 2 surface mesh only; elements: "hex", "wedge"
(triangle caps swept into wedges) or "mixed"; threads: 0 for all cores (the
mesh does not depend on it); imprint: merge touching solids so they share
nodes; finer_retries: a volume its scheme fails on after planning is meshed
again at half its size, at most this many times (0-4; a warning says so);
decompose: "auto" cuts a volume no scheme applies to into pieces that one
does (Mesh.decomposition lists the cuts), "off" refuses it instead;
min_scaled_jacobian: a floor (-1 to 1) as a journal's failing quality check:
a volume below it is first meshed again at half its size (finer_retries
times at most, a warning says so), and below it still, Mesh.checks says the
check failed. Returns a Mesh. Raises InputError or MeshingError.)doc");
  m.def("run", &run, py::arg("journal"), py::arg("threads") = 0,
        R"doc(Runs a journal (.xml) as `cooperage run` does: geometry, meshing, quality
checks, exports and reports. Returns a Mesh whose `written` lists the files
written (none when a quality check with action="fail" failed: see `checks`
and `exports_skipped`). Raises InputError or MeshingError.)doc");
  m.def("plan", &plan_file, py::arg("model_or_journal"), py::arg("size") = py::none(),
        py::arg("dim") = 3, py::arg("elements") = py::none(), py::arg("imprint") = py::none(),
        py::arg("decompose") = py::none(),
        R"doc(The scheme the selector picks for every volume and surface, and why, without
meshing (as `cooperage plan --json`). size (a length or "D/N", as for mesh())
overrides the journal's; without
any size the interval feasibility check is skipped. dim=2 plans the surfaces
alone, as mesh(..., dim=2) does. elements, imprint and decompose plan a CAD
file as mesh() with them would mesh it (a journal sets imprint itself;
elements and decompose override its <mesh>). Returns a list of dicts:
entity, dim, id, scheme, score, reason, pinned, candidates.)doc");
}
