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
  ${CMAKE_CURRENT_LIST_DIR}/face_box.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_pieces.cpp
  PRIVATE_DEPS TBB::tbb)

# OCCT toolkits most runs never need, in modules of their own opened on
# first use (core/lazy_module.h): STEP (step_module.cpp), IGES
# (iges_module.cpp) and lofts (loft_module.cpp), built beside
# libcooperage_framework.
cooperage_framework_module(occ_step PART occ OCCT
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/step_module.cpp
  LIBS ${OCCT_LIBRARIES} ${OCCT_STEP_LIBRARIES})
# The toolkits that answer most of the module's symbol lookups first
# (cmake/CooperageLookupOrder.cmake; counted with LD_DEBUG=bindings).
cooperage_lookup_first(cooperage_occ_step
  ${OCCT_TKSTEPBase_LIBRARY} ${OCCT_TKXSBase_LIBRARY} ${OCCT_TKSTEPAttr_LIBRARY}
  ${OCCT_TKSTEP_LIBRARY} ${OCCT_TKSTEP209_LIBRARY} ${OCCT_TKernel_LIBRARY})
cooperage_framework_module(occ_iges PART occ OCCT
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/iges_module.cpp
  LIBS ${OCCT_LIBRARIES} ${OCCT_IGES_LIBRARIES})
cooperage_framework_module(occ_loft PART occ OCCT
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/loft_module.cpp
  LIBS ${OCCT_LIBRARIES} ${OCCT_LOFT_LIBRARIES})
