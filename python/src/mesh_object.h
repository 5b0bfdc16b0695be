// cooperage.Mesh: the result of cooperage.mesh() / cooperage.run(), holding
// the whole run (model, mesh, plan, quality, timings) on the C++ side.
// Arrays handed to Python view memory the Mesh owns and keep it alive.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "framework/pipeline/mesher.h"
#include "mesh_arrays.h"

namespace cooperage::python {

struct MeshObject {
  pipeline::RunResult run;
  std::string title;                ///< what was meshed: the CAD or journal file
  io::GroupSettings groups;         ///< the journal's blocks, side sets, node sets (write())
  std::optional<CellArrays> cells;  ///< built on first use
};

/// Defines the Python class cooperage.Mesh.
void bind_mesh(pybind11::module_& m);

}  // namespace cooperage::python
