cooperage_framework_part(occ OCCT SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/silence.cpp
  ${CMAKE_CURRENT_LIST_DIR}/workbench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/primitives.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loft.cpp
  ${CMAKE_CURRENT_LIST_DIR}/booleans.cpp
  ${CMAKE_CURRENT_LIST_DIR}/import.cpp
  ${CMAKE_CURRENT_LIST_DIR}/write.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_projector.cpp
  ${CMAKE_CURRENT_LIST_DIR}/face_facts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_pieces.cpp
  PRIVATE_DEPS TBB::tbb)
