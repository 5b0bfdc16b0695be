// STEP and IGES through a module per format (step_module.cpp,
// iges_module.cpp), loaded on first use: a process that reads no STEP or
// IGES file never maps OCCT's data-exchange toolkits, and a STEP run never
// maps IGES's (issue 20, start-up). Private to framework/geometry/occ (OCCT
// types).
#pragma once

#include "framework/geometry/occ/exchange_units.h"

#include <TopoDS_Shape.hxx>

#include <string>

namespace cooperage::occ::exchange {

enum class Format { Step = 0, Iges = 1 };

/// Loads the format's module now (idempotent, thread-safe). Call it before fork():
/// the child of a forked reader must not be the first to run the loader.
/// Throws MeshingError(Internal) naming every place looked in.
void load(Format format);

/// Reads a file; `unit` is the default on entry and the file's on return.
/// Throws MeshingError(ParseError) "<path>: <reason>" when the reader fails.
TopoDS_Shape read(Format format, const std::string& path, Unit& unit);

/// Writes `shape`; false when the kernel could not.
bool write(Format format, const std::string& path, const TopoDS_Shape& shape,
           const std::string& unit_name);

}  // namespace cooperage::occ::exchange
