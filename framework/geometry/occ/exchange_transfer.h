// What the STEP and the IGES module (step_module.cpp, iges_module.cpp) share:
// their C interface (exchange.cpp finds it by name), its error text and the
// transfer of a read file's roots. Included only by those two modules.
#pragma once

#include "framework/geometry/occ/exchange_units.h"

#include <Interface_Static.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>

#include <cstdio>

namespace cooperage::occ::exchange_module {

inline int fail(char* error, size_t size, const char* why) {
  std::snprintf(error, size, "%s", why);
  return 1;
}

/// The read file's roots as one shape, in the file's unit (the cascade unit
/// set for the transfer only, so the kernel does not convert).
inline int transfer(XSControl_Reader& reader, const char* kind, TopoDS_Shape* shape,
                    const Unit& unit, char* error, size_t size) {
  char why[64];
  Interface_Static::SetCVal("xstep.cascade.unit", unit.occt);
  if (reader.NbRootsForTransfer() <= 0) {
    std::snprintf(why, sizeof why, "the %s file holds no shape", kind);
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    return fail(error, size, why);
  }
  reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  if (reader.NbShapes() <= 0) {
    std::snprintf(why, sizeof why, "no shape could be read from the %s file", kind);
    return fail(error, size, why);
  }
  *shape = reader.OneShape();
  return 0;
}

}  // namespace cooperage::occ::exchange_module

// The interface each module defines. OCCT objects cross it by pointer (one
// OCCT in the process); errors come back as text, kernel exceptions
// propagate to the caller's guard (detail::guarded).
extern "C" {

/// The interface version (kExchangeModuleAbi, exchange_units.h).
__attribute__((visibility("default"))) int cooperage_exchange_abi();

/// Reads a file of the module's format into *shape, in the file's length
/// unit (*unit: in, the default; out, the file's). 0 on success; otherwise
/// the reason in `error`.
__attribute__((visibility("default"))) int cooperage_exchange_read(const char* path,
                                                                   TopoDS_Shape* shape,
                                                                   cooperage::occ::Unit* unit,
                                                                   char* error, size_t size);

/// Writes *shape in the module's format, in the unit named (an OCCT unit
/// name, "MM", "INCH", ...). 0 on success.
__attribute__((visibility("default"))) int cooperage_exchange_write(const char* path,
                                                                    const TopoDS_Shape* shape,
                                                                    const char* unit_name);
}
