cooperage_framework_part(intervals SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/interval_problem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/deviation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ilp.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solve.cpp
  PRIVATE_DEPS PkgConfig::CBC)
