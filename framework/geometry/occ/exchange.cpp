#include "framework/geometry/occ/exchange.h"

#include "framework/core/error.h"
#include "framework/core/lazy_module.h"

#include <dlfcn.h>

#include <mutex>

namespace cooperage::occ::exchange {
namespace {

using ReadFn = int (*)(int, const char*, TopoDS_Shape*, Unit*, char*, size_t);
using WriteFn = int (*)(int, const char*, const TopoDS_Shape*, const char*);

struct Api {
  ReadFn read = nullptr;
  WriteFn write = nullptr;
};

const Api& api() {
  static Api loaded;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle =
        open_module("libcooperage_occ_exchange.so", "cooperage_exchange_abi", /*abi=*/1);
    loaded.read = reinterpret_cast<ReadFn>(dlsym(handle, "cooperage_exchange_read"));
    loaded.write = reinterpret_cast<WriteFn>(dlsym(handle, "cooperage_exchange_write"));
    if (loaded.read == nullptr || loaded.write == nullptr)
      throw MeshingError(ErrorCode::Internal,
                         "libcooperage_occ_exchange.so lacks its read or write function");
  });
  return loaded;
}

}  // namespace

void load() { api(); }

TopoDS_Shape read(Format format, const std::string& path, Unit& unit) {
  TopoDS_Shape shape;
  char error[256] = {0};
  if (api().read(static_cast<int>(format), path.c_str(), &shape, &unit, error, sizeof error) != 0)
    throw MeshingError(ErrorCode::ParseError, path + ": " + error);
  return shape;
}

bool write(Format format, const std::string& path, const TopoDS_Shape& shape,
           const std::string& unit_name) {
  return api().write(static_cast<int>(format), path.c_str(), &shape, unit_name.c_str()) == 0;
}

}  // namespace cooperage::occ::exchange
