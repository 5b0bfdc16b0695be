#include "framework/geometry/occ/exchange.h"

#include "framework/core/error.h"
#include "framework/core/lazy_module.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

namespace cooperage::occ::exchange {
namespace {

using ReadFn = int (*)(const char*, TopoDS_Shape*, Unit*, char*, size_t);
using WriteFn = int (*)(const char*, const TopoDS_Shape*, const char*);

/// The module of one format (step_module.cpp, iges_module.cpp).
struct Api {
  ReadFn read = nullptr;
  WriteFn write = nullptr;
};

const Api& api(Format format) {
  static Api loaded[2];
  static std::once_flag once[2];
  const int k = static_cast<int>(format);
  std::call_once(once[k], [k] {
    const char* file = k == static_cast<int>(Format::Step) ? "libcooperage_occ_step.so"
                                                           : "libcooperage_occ_iges.so";
    void* handle = open_module(file, "cooperage_exchange_abi", kExchangeModuleAbi);
    loaded[k].read = reinterpret_cast<ReadFn>(dlsym(handle, "cooperage_exchange_read"));
    loaded[k].write = reinterpret_cast<WriteFn>(dlsym(handle, "cooperage_exchange_write"));
    if (loaded[k].read == nullptr || loaded[k].write == nullptr)
      throw MeshingError(ErrorCode::Internal,
                         std::string(file) + " lacks its read or write function");
  });
  return loaded[k];
}

}  // namespace

void load(Format format) { api(format); }

TopoDS_Shape read(Format format, const std::string& path, Unit& unit) {
  TopoDS_Shape shape;
  char error[256] = {0};
  if (api(format).read(path.c_str(), &shape, &unit, error, sizeof error) != 0)
    throw MeshingError(ErrorCode::ParseError, path + ": " + error);
  return shape;
}

bool write(Format format, const std::string& path, const TopoDS_Shape& shape,
           const std::string& unit_name) {
  return api(format).write(path.c_str(), &shape, unit_name.c_str()) == 0;
}

}  // namespace cooperage::occ::exchange
