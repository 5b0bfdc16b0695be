# framework/quality: Verdict-equivalent element quality metrics and reports.
cooperage_framework_part(quality SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/metric.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hex_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/wedge_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quad_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tri_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/evaluate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/summary.cpp
  PRIVATE_DEPS TBB::tbb)
