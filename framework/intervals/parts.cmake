cooperage_framework_part(intervals SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/interval_problem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/deviation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ilp.cpp
  ${CMAKE_CURRENT_LIST_DIR}/separable_optimum.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solve.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve_sizing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sharp_corner_sizing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/faceting_budget.cpp
  PRIVATE_DEPS ${CMAKE_DL_LIBS})

# CBC in a module of its own, opened on the first solve (cbc_problem.h).
cooperage_framework_module(cbc PART intervals
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/cbc_module.cpp LIBS PkgConfig::CBC)
