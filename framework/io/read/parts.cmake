# Mesh file readers (.exo via libexodusII, .msh, .vtu via tinyxml2) for the
# `cooperage quality` report.
cooperage_framework_part(io_read
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/read_common.cpp
    ${CMAKE_CURRENT_LIST_DIR}/read_mesh_file.cpp
    ${CMAKE_CURRENT_LIST_DIR}/exodus_reader.cpp
    ${CMAKE_CURRENT_LIST_DIR}/msh_reader.cpp
    ${CMAKE_CURRENT_LIST_DIR}/vtu_reader.cpp
  PRIVATE_DEPS cooperage_exodus_lazy tinyxml2::tinyxml2)
