// Opening one of Cooperage's own modules (libcooperage_*.so) on first use.
// Each links libraries that many runs never need or need only later (OCCT's
// STEP/IGES: occ/exchange.h; lofts: occ/loft.cpp; CBC: intervals/ilp.cpp),
// so no process maps them at start-up, where their symbol relocations cost
// every run (issue 20).
#pragma once

namespace cooperage {

/// The handle of module `file` ("libcooperage_occ_step.so"), opened
/// with its toolkits looking up symbols among themselves first
/// (RTLD_DEEPBIND, except under sanitizers). Looks in $COOPERAGE_MODULE_DIR,
/// beside the binary holding this code (the installed or built framework),
/// the build directory, then the loader's own search; a module whose
/// `abi_symbol` function does not return `abi` is skipped. Throws
/// MeshingError(Internal) naming every place looked in. Not cached: callers
/// open once (std::call_once) and keep the handle.
void* open_module(const char* file, const char* abi_symbol, int abi);

}  // namespace cooperage
