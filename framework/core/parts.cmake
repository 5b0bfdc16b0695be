cooperage_framework_part(core SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/error.cpp
  ${CMAKE_CURRENT_LIST_DIR}/log.cpp
  ${CMAKE_CURRENT_LIST_DIR}/text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/isolate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/readable_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lazy_module.cpp)
# The framework's modules (libcooperage_*.so: occ/parts.cmake,
# intervals/parts.cmake) are built beside libcooperage_framework, where the
# loader looks first; tests that link the framework's objects find them in
# the build directory.
target_compile_definitions(cooperage_fw_core PRIVATE
  COOPERAGE_MODULE_BUILD_DIR="${CMAKE_CURRENT_BINARY_DIR}")
