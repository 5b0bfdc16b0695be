# Mesh exporters: Exodus II (libexodusII), Gmsh 4.1, VTK .vtu, Abaqus .inp, and
# .obj/.off/.stl/.ply through OpenMesh.
cooperage_framework_part(io_export
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/export_common.cpp
    ${CMAKE_CURRENT_LIST_DIR}/mesh_groups.cpp
    ${CMAKE_CURRENT_LIST_DIR}/exodus_writer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/netcdf_classic_data.cpp
    ${CMAKE_CURRENT_LIST_DIR}/msh_writer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/vtu_writer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/inp_writer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/surface_writer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/write_mesh.cpp
    ${CMAKE_CURRENT_LIST_DIR}/../exodus_lazy.cpp
  PRIVATE_DEPS cooperage_exodus_lazy TBB::tbb OpenMeshCore)
