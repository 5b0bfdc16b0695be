cooperage_framework_part(mesh SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/mesh_db.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve_spacing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/corner_sine.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loop_nodes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/split_poor_quads.cpp
  ${CMAKE_CURRENT_LIST_DIR}/strip_elements.cpp
  ${CMAKE_CURRENT_LIST_DIR}/improve_split_nodes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tfi.cpp
  ${CMAKE_CURRENT_LIST_DIR}/corner_untangle.cpp)
