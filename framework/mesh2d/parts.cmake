# framework/mesh2d: constrained Delaunay triangulation + Delaunay refinement on
# plain 2D value types, for any scheme that needs triangles in a plane.
cooperage_framework_part(mesh2d SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/predicates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cdt.cpp
  ${CMAKE_CURRENT_LIST_DIR}/refine.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangulate.cpp)
