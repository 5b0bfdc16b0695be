cooperage_framework_part(intervals SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/interval_problem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/deviation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ilp.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solve.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve_sizing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/faceting_budget.cpp
  PRIVATE_DEPS ${CMAKE_DL_LIBS})

# CBC in a module of its own, opened on the first solve (cbc_problem.h),
# built beside libcooperage_framework (core/lazy_module.h).
add_library(cooperage_cbc MODULE ${CMAKE_CURRENT_LIST_DIR}/cbc_module.cpp)
target_include_directories(cooperage_cbc PRIVATE ${PROJECT_SOURCE_DIR})
target_link_libraries(cooperage_cbc PRIVATE PkgConfig::CBC cooperage_warnings)
set_target_properties(cooperage_cbc PROPERTIES
  PREFIX "lib" CXX_VISIBILITY_PRESET hidden
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_dependencies(cooperage_fw_intervals cooperage_cbc)
