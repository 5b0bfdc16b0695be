# framework/mesh2d: the one 2D layer -- exact predicates, constrained Delaunay
# triangulation + Delaunay refinement on plain 2D value types, and the
# flattener that gives every 2D scheme its plane (surface_chart.h).
cooperage_framework_part(mesh2d SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/predicates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cdt.cpp
  ${CMAKE_CURRENT_LIST_DIR}/refine.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangulate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/conformal_map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loop_parameters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loop_validity.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangle_locator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/touching_loops.cpp
  ${CMAKE_CURRENT_LIST_DIR}/parity_ear.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_chart.cpp)
