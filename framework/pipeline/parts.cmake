cooperage_framework_part(pipeline SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/build_geometry.cpp)
