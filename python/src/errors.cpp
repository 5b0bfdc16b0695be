#include "errors.h"

#include "framework/core/error.h"

namespace py = pybind11;

namespace cooperage::python {
namespace {

PyObject* g_error = nullptr;
PyObject* g_input_error = nullptr;
PyObject* g_meshing_error = nullptr;

// The command line's exit code 2 cases (app/main.cpp): the input, not
// Cooperage, has to change.
bool is_input_error(ErrorCode code) {
  switch (code) {
    case ErrorCode::InvalidInput:
    case ErrorCode::FileNotFound:
    case ErrorCode::ParseError:
    case ErrorCode::GeometryError:
    case ErrorCode::NotSupported:
    case ErrorCode::NotApplicable:
    case ErrorCode::Infeasible: return true;
    case ErrorCode::MeshingFailed:
    case ErrorCode::Internal: return false;
  }
  return false;
}

void raise(const MeshingError& e) {
  PyObject* type = is_input_error(e.code()) ? g_input_error : g_meshing_error;
  py::object exc = py::reinterpret_borrow<py::object>(type)(e.what());
  exc.attr("code") = to_string(e.code());
  exc.attr("entity") = e.entity().dim < 0
                           ? py::object(py::none())
                           : py::object(py::make_tuple(e.entity().dim, e.entity().id));
  PyErr_SetObject(type, exc.ptr());
}

PyObject* new_exception(py::module_& m, const char* name, const char* doc, PyObject* base) {
  const std::string qualified = std::string("cooperage.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));  // the module keeps a reference for ever
  return type;
}

}  // namespace

void register_errors(py::module_& m) {
  g_error = new_exception(m, "Error",
                          "Base of Cooperage's errors. str(e) is the one-line message of the "
                          "command line; e.code names the kind (\"parse error\", ...), e.entity "
                          "is (dimension, id) of the entity it is about, or None.",
                          PyExc_RuntimeError);
  g_input_error = new_exception(m, "InputError",
                                "Bad input: a missing or malformed file, a bad argument or journal "
                                "line, a geometry the CAD kernel cannot handle, an entity no "
                                "scheme applies to, infeasible interval counts (the command "
                                "line's exit code 2).",
                                g_error);
  g_meshing_error = new_exception(m, "MeshingError",
                                  "A scheme failed on an entity it had accepted, or an internal "
                                  "error.",
                                  g_error);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const MeshingError& e) {
      raise(e);
    }
  });
}

}  // namespace cooperage::python
