cooperage_framework_part(scheme SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/role.cpp
  ${CMAKE_CURRENT_LIST_DIR}/registry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/refusals.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plugin_loader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vertex_angles.cpp
  PRIVATE_DEPS ${CMAKE_DL_LIBS})
