// The Exodus II library, loaded on first use instead of at start-up.
//
// Debian's libexoIIv2c is built on the MPI build of netCDF, so linking it
// made every `cooperage` process load an MPI and HDF5 stack (~40 shared
// libraries, ~50 ms of CPU before main, issue 20) even when no Exodus file
// is read or written. Include this header after <exodusII.h> in a file that
// calls the library: the ex_* and nc_* functions used by Cooperage become
// calls through a table filled by dlopen/dlsym the first time one is made.
// The table covers exactly the functions used; add a line to both lists
// below to use another.
#pragma once

#include <exodusII.h>
#include <netcdf.h>

namespace cooperage::io::exodus_lazy {

// clang-format off
#define COOPERAGE_EXODUS_FUNCTIONS(X)                                                          \
  X(ex_create_int) X(ex_open_int) X(ex_close) X(ex_set_option) X(ex_put_init)               \
  X(ex_put_coord_names) X(ex_put_block) X(ex_put_sets) X(ex_put_names)                         \
  X(ex_put_partial_coord) X(ex_put_set) X(ex_put_info) X(ex_get_init_ext) X(ex_inquire_int)                   \
  X(ex_set_max_name_length) X(ex_get_coord) X(ex_get_ids) X(ex_get_block) X(ex_get_conn)      \
  X(ex_get_name) X(ex_set_int64_status) X(nc_inq_varid) X(nc_put_vara_int) X(nc_redef) X(nc__enddef)        \
  X(nc__open) X(nc_close) X(nc_put_vara_double)
// clang-format on

struct Api {
#define COOPERAGE_EXODUS_MEMBER(f) decltype(&::f) f = nullptr;
  COOPERAGE_EXODUS_FUNCTIONS(COOPERAGE_EXODUS_MEMBER)
#undef COOPERAGE_EXODUS_MEMBER
};

/// The loaded library; throws MeshingError(Internal) naming the library and
/// the loader's reason when it or one of the functions cannot be found.
const Api& api();

}  // namespace cooperage::io::exodus_lazy

#define ex_create_int(...) ::cooperage::io::exodus_lazy::api().ex_create_int(__VA_ARGS__)
#define ex_open_int(...) ::cooperage::io::exodus_lazy::api().ex_open_int(__VA_ARGS__)
#define ex_close(...) ::cooperage::io::exodus_lazy::api().ex_close(__VA_ARGS__)
#define ex_set_option(...) ::cooperage::io::exodus_lazy::api().ex_set_option(__VA_ARGS__)
#define ex_put_init(...) ::cooperage::io::exodus_lazy::api().ex_put_init(__VA_ARGS__)
#define ex_put_coord_names(...) ::cooperage::io::exodus_lazy::api().ex_put_coord_names(__VA_ARGS__)
#define ex_put_block(...) ::cooperage::io::exodus_lazy::api().ex_put_block(__VA_ARGS__)
#define ex_put_sets(...) ::cooperage::io::exodus_lazy::api().ex_put_sets(__VA_ARGS__)
#define ex_put_names(...) ::cooperage::io::exodus_lazy::api().ex_put_names(__VA_ARGS__)
#define ex_put_partial_coord(...) \
  ::cooperage::io::exodus_lazy::api().ex_put_partial_coord(__VA_ARGS__)
#define ex_put_set(...) ::cooperage::io::exodus_lazy::api().ex_put_set(__VA_ARGS__)
#define ex_put_info(...) ::cooperage::io::exodus_lazy::api().ex_put_info(__VA_ARGS__)
#define ex_get_init_ext(...) ::cooperage::io::exodus_lazy::api().ex_get_init_ext(__VA_ARGS__)
#define ex_inquire_int(...) ::cooperage::io::exodus_lazy::api().ex_inquire_int(__VA_ARGS__)
#define ex_set_max_name_length(...) \
  ::cooperage::io::exodus_lazy::api().ex_set_max_name_length(__VA_ARGS__)
#define ex_get_coord(...) ::cooperage::io::exodus_lazy::api().ex_get_coord(__VA_ARGS__)
#define ex_get_ids(...) ::cooperage::io::exodus_lazy::api().ex_get_ids(__VA_ARGS__)
#define ex_get_block(...) ::cooperage::io::exodus_lazy::api().ex_get_block(__VA_ARGS__)
#define ex_get_conn(...) ::cooperage::io::exodus_lazy::api().ex_get_conn(__VA_ARGS__)
#define ex_get_name(...) ::cooperage::io::exodus_lazy::api().ex_get_name(__VA_ARGS__)
#define ex_set_int64_status(...) \
  ::cooperage::io::exodus_lazy::api().ex_set_int64_status(__VA_ARGS__)
#define nc_inq_varid(...) ::cooperage::io::exodus_lazy::api().nc_inq_varid(__VA_ARGS__)
#define nc_put_vara_int(...) ::cooperage::io::exodus_lazy::api().nc_put_vara_int(__VA_ARGS__)
#define nc_redef(...) ::cooperage::io::exodus_lazy::api().nc_redef(__VA_ARGS__)
#define nc__enddef(...) ::cooperage::io::exodus_lazy::api().nc__enddef(__VA_ARGS__)
#define nc__open(...) ::cooperage::io::exodus_lazy::api().nc__open(__VA_ARGS__)
#define nc_close(...) ::cooperage::io::exodus_lazy::api().nc_close(__VA_ARGS__)
#define nc_put_vara_double(...) ::cooperage::io::exodus_lazy::api().nc_put_vara_double(__VA_ARGS__)
