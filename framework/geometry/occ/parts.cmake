cooperage_framework_part(occ OCCT SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/silence.cpp
  ${CMAKE_CURRENT_LIST_DIR}/workbench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/primitives.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loft.cpp
  ${CMAKE_CURRENT_LIST_DIR}/booleans.cpp
  ${CMAKE_CURRENT_LIST_DIR}/exchange.cpp
  ${CMAKE_CURRENT_LIST_DIR}/import.cpp
  ${CMAKE_CURRENT_LIST_DIR}/write.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_projector.cpp
  ${CMAKE_CURRENT_LIST_DIR}/face_facts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_pieces.cpp
  PRIVATE_DEPS TBB::tbb)

# OCCT toolkits most runs never need, in modules of their own opened on
# first use (core/lazy_module.h): STEP/IGES (exchange_module.cpp) and lofts
# (loft_module.cpp), built beside libcooperage_framework.
foreach(_module exchange loft)
  set(_target cooperage_occ_${_module})
  add_library(${_target} MODULE ${CMAKE_CURRENT_LIST_DIR}/${_module}_module.cpp)
  target_include_directories(${_target} PRIVATE ${PROJECT_SOURCE_DIR})
  target_include_directories(${_target} SYSTEM PRIVATE ${OCCT_INCLUDE_DIR})
  target_link_libraries(${_target} PRIVATE ${OCCT_LIBRARIES} cooperage_warnings)
  set_target_properties(${_target} PROPERTIES
    PREFIX "lib" CXX_VISIBILITY_PRESET hidden
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  add_dependencies(cooperage_fw_occ ${_target})
endforeach()
target_link_libraries(cooperage_occ_exchange PRIVATE ${OCCT_EXCHANGE_LIBRARIES})
target_link_libraries(cooperage_occ_loft PRIVATE ${OCCT_LOFT_LIBRARIES})
