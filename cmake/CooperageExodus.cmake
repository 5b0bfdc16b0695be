# Exodus II from Debian's libexodusii-dev (a static libexoIIv2c without a
# CMake config) on top of netCDF. Defines the imported target cooperage_exodus.
find_path(EXODUS_INCLUDE_DIR exodusII.h REQUIRED)
find_library(EXODUS_LIBRARY exoIIv2c REQUIRED)
find_package(netCDF QUIET CONFIG)
if(TARGET netCDF::netcdf)
  set(_exodus_netcdf netCDF::netcdf)
else()
  find_library(NETCDF_LIBRARY netcdf REQUIRED)
  set(_exodus_netcdf ${NETCDF_LIBRARY})
endif()
add_library(cooperage_exodus INTERFACE IMPORTED)
set_target_properties(cooperage_exodus PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${EXODUS_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${EXODUS_LIBRARY};${_exodus_netcdf}")
# The library itself is loaded at run time on first use
# (framework/io/exodus_lazy.h): Debian's build drags in an MPI stack, which
# cost every process ~50 ms of start-up. The framework gets the headers and
# the file to fall back on when the loader's search path misses it.
get_filename_component(EXODUS_LIBRARY_FILE "${EXODUS_LIBRARY}" REALPATH)
add_library(cooperage_exodus_lazy INTERFACE IMPORTED)
set_target_properties(cooperage_exodus_lazy PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${EXODUS_INCLUDE_DIR}"
  INTERFACE_COMPILE_DEFINITIONS "COOPERAGE_EXODUS_LIBRARY_FILE=\"${EXODUS_LIBRARY_FILE}\""
  INTERFACE_LINK_LIBRARIES "${CMAKE_DL_LIBS}")
