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
  ${CMAKE_CURRENT_LIST_DIR}/model_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_pieces.cpp
  PRIVATE_DEPS TBB::tbb)

# OCCT's STEP/IGES readers and writers in a module of their own, loaded by
# exchange.cpp on the first STEP or IGES file (exchange_module.cpp says why).
# Built beside libcooperage_framework, where the loader looks first; tests
# that link the framework's objects find it by its build path.
add_library(cooperage_occ_exchange MODULE ${CMAKE_CURRENT_LIST_DIR}/exchange_module.cpp)
target_include_directories(cooperage_occ_exchange PRIVATE ${PROJECT_SOURCE_DIR})
target_include_directories(cooperage_occ_exchange SYSTEM PRIVATE ${OCCT_INCLUDE_DIR})
target_link_libraries(cooperage_occ_exchange PRIVATE ${OCCT_EXCHANGE_LIBRARIES} ${OCCT_LIBRARIES}
                      cooperage_warnings)
set_target_properties(cooperage_occ_exchange PROPERTIES
  PREFIX "lib" CXX_VISIBILITY_PRESET hidden
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
target_compile_definitions(cooperage_fw_occ PRIVATE
  COOPERAGE_EXCHANGE_BUILD_PATH="$<TARGET_FILE:cooperage_occ_exchange>")
add_dependencies(cooperage_fw_occ cooperage_occ_exchange)
