#include "mesh_object.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "framework/core/error.h"
#include "framework/decompose/report_text.h"
#include "framework/io/export/write_mesh.h"
#include "framework/report/html_report.h"
#include "framework/report/report_from_run.h"
#include "plan_dicts.h"

namespace py = pybind11;

namespace cooperage::python {
namespace {

using Holder = std::shared_ptr<MeshObject>;

// A read-only numpy view of `data` whose lifetime is tied to `owner`.
template <class T>
py::array view(const T* data, std::size_t rows, std::size_t cols, py::handle owner) {
  py::array_t<T> a({rows, cols}, {cols * sizeof(T), sizeof(T)}, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

template <class T>
py::array copy_1d(const std::vector<T>& values) {
  py::array_t<T> a(values.size());
  std::copy(values.begin(), values.end(), a.mutable_data());
  return std::move(a);
}

const CellArrays& cells_of(MeshObject& m) {
  if (!m.cells) m.cells = cell_arrays(m.run.mesh.mesh);
  return *m.cells;
}

py::array points(py::object self) {
  auto& m = *self.cast<Holder>();
  const auto& coords = m.run.mesh.mesh.coords();
  // Eigen::Vector3d is three packed doubles, so the node vector is an n x 3 array.
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  return view(coords.empty() ? nullptr : coords.front().data(), coords.size(), 3, self);
}

py::dict cells(py::object self) {
  auto& m = *self.cast<Holder>();
  const CellArrays& c = cells_of(m);
  py::dict out;
  for (CellKind kind : kCellKinds) {
    const auto& flat = c[static_cast<std::size_t>(kind)];
    if (flat.empty()) continue;
    const auto k = static_cast<std::size_t>(corner_count(kind));
    out[meshio_name(kind)] = view(flat.data(), flat.size() / k, k, self);
  }
  return out;
}

py::dict cell_sets_of(const MeshObject& m) {
  py::dict out;
  for (const CellSet& s : cell_sets(m.run.mesh.mesh)) {
    py::str name(s.name);
    if (!out.contains(name)) out[name] = py::dict();
    out[name].cast<py::dict>()[meshio_name(s.kind)] = copy_1d(s.indices);
  }
  return out;
}

py::dict quality_of(MeshObject& m, const std::string& metric_name) {
  const auto metric = quality::metric_from_string(metric_name);
  if (!metric) {
    std::string names;
    for (quality::Metric k : quality::kAllMetrics) {
      names += (names.empty() ? "" : ", ") + std::string(quality::to_string(k));
    }
    throw MeshingError(ErrorCode::InvalidInput,
                       "unknown quality metric \"" + metric_name + "\"; known: " + names);
  }
  std::array<std::optional<std::vector<double>>, 4> values;
  {
    py::gil_scoped_release release;
    values = cell_quality(m.run.mesh.mesh, m.run.model, *metric);
  }
  const CellArrays& c = cells_of(m);
  py::dict out;
  for (CellKind kind : kCellKinds) {
    const auto& v = values[static_cast<std::size_t>(kind)];
    if (v && !c[static_cast<std::size_t>(kind)].empty()) out[meshio_name(kind)] = copy_1d(*v);
  }
  return out;
}

py::list checks_of(const MeshObject& m) {
  py::list out;
  for (const auto& c : m.run.quality.checks) {
    py::dict d;
    d["metric"] = c.check.metric;
    d["min"] = c.check.min ? py::object(py::float_(*c.check.min)) : py::object(py::none());
    d["max"] = c.check.max ? py::object(py::float_(*c.check.max)) : py::object(py::none());
    d["action"] = c.check.action == io::QualityCheck::Action::Fail ? "fail" : "warn";
    d["violations"] = c.violations;
    d["failed"] = c.failed;
    out.append(d);
  }
  return out;
}

std::string repr(const MeshObject& m) {
  const auto& db = m.run.mesh.mesh;
  std::string s =
      "<cooperage.Mesh of '" + m.title + "': " + std::to_string(db.node_count()) + " points";
  const std::pair<const char*, std::size_t> counts[] = {{"hexahedra", db.hex_count()},
                                                        {"wedges", db.wedge_count()},
                                                        {"quads", db.quad_count()},
                                                        {"triangles", db.tri_count()}};
  for (const auto& [name, n] : counts) {
    if (n) s += ", " + std::to_string(n) + " " + name;
  }
  return s + ">";
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<MeshObject, Holder>(m, "Mesh", R"doc(
A mesh made by cooperage.mesh() or cooperage.run().

Arrays follow meshio's conventions: ``points`` is a read-only float64 (n, 3)
view of the mesh's own nodes (no copy; copy it to modify), ``cells`` maps
"hexahedron", "wedge", "quad", "triangle" to read-only int64 arrays of
0-based node indices in meshio's node order (VTK's; wedges as in Gmsh and
Exodus). Arrays stay valid after the Mesh object is gone.)doc")
      .def_property_readonly("points", &points, "Node coordinates, float64 (n, 3), read-only.")
      .def_property_readonly("cells", &cells,
                             "Cell type -> int64 (cells, corners) node indices: the hexahedra of "
                             "every volume in id order, then wedges; the quads and triangles of "
                             "every meshed surface in id order.")
      .def_property_readonly(
          "cell_sets", [](const MeshObject& self) { return cell_sets_of(self); },
          "\"volume 2\" / \"surface 12\" -> {cell type: int64 indices into cells[type]}.")
      .def("quality", &quality_of, py::arg("metric") = "scaled_jacobian",
           "Per-cell quality: cell type -> float64 array in the order of cells[type] (types "
           "the metric is not defined for are left out). Metrics: scaled_jacobian, jacobian, "
           "skew, taper, aspect_frobenius, edge_ratio, shape, relative_size (Verdict's).")
      .def(
          "write",
          [](const MeshObject& self, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            io::ExportOptions options;
            options.groups = self.groups;
            io::write_mesh(path.string(), self.run.mesh.mesh, self.run.model, options);
          },
          py::arg("path"),
          "Writes the mesh; the extension picks the format: .exo/.e/.g Exodus II, .msh Gmsh 4.1, "
          ".vtu VTK, .inp Abaqus. A journal's <block>, <sideset> and <nodeset> are kept (names "
          "included). Atomic: a failure leaves no file.")
      .def(
          "report",
          [](const MeshObject& self, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            report::write_report(path.string(), report::report_input(self.run, self.title));
          },
          py::arg("path"),
          "Writes the self-contained HTML report (pictures coloured by scaled Jacobian, "
          "quality histograms, plan, time per stage, warnings). Atomic.")
      .def_property_readonly(
          "warnings",
          [](const MeshObject& self) {
            std::vector<std::string> out;
            for (const auto& w : self.run.mesh.warnings) out.push_back(w.text());
            return out;
          },
          "What the run gave up or found suspicious without failing, one sentence each.")
      .def_property_readonly(
          "plan", [](const MeshObject& self) { return plan_entries(self.run.mesh.plan); },
          "The scheme of every volume and surface: dicts (entity, dim, id, scheme, reason, "
          "details).")
      .def_property_readonly(
          "decomposition",
          [](const MeshObject& self) { return decompose::report_lines(self.run.decomposition); },
          "The automatic cuts made, one line each as `cooperage mesh` prints them (empty "
          "when none were needed).")
      .def_property_readonly(
          "stages",
          [](const MeshObject& self) {
            py::dict out;
            for (const auto& s : self.run.stages) out[py::str(s.stage)] = s.seconds;
            return out;
          },
          "Wall time per stage in seconds, in run order.")
      .def_property_readonly(
          "written", [](const MeshObject& self) { return self.run.written; },
          "Files the run wrote (a journal's exports and reports).")
      .def_property_readonly(
          "checks", [](const MeshObject& self) { return checks_of(self); },
          "A journal's quality checks: dicts (metric, min, max, action, violations, failed).")
      .def_property_readonly(
          "exports_skipped", [](const MeshObject& self) { return self.run.exports_skipped; },
          "True when a failing quality check stopped the journal's exports.")
      .def_readonly("source", &MeshObject::title, "The CAD or journal file meshed.")
      .def("__repr__", &repr);
}

}  // namespace cooperage::python
