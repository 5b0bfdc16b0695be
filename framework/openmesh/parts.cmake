# OpenMesh half-edge surface meshes (to_openmesh / from_openmesh). Never
# compiled with OCCT's headers (its Handle macro breaks OpenMesh's).
cooperage_framework_part(openmesh
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/surface_mesh.cpp
  PRIVATE_DEPS OpenMeshCore)
# GCC 12 reports OpenMesh's own PropertyT<Vec3d>::push_back() (it appends a
# default-constructed point, overwritten at once by add_vertex) as "may be
# used uninitialized" when inlined here; the warning is about OpenMesh's
# header, not this code.
target_compile_options(cooperage_fw_openmesh PRIVATE
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
