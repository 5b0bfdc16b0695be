# OpenMesh half-edge surface meshes (to_openmesh / from_openmesh). Never
# compiled with OCCT's headers (its Handle macro breaks OpenMesh's).
cooperage_framework_part(openmesh
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/surface_mesh.cpp
  PRIVATE_DEPS OpenMeshCore)
