# OpenCASCADE 7.6 from Debian's libocct-*-dev. Debian's OpenCASCADEConfig.cmake
# refuses to load unless the visualisation and OCAF modules are installed too
# (its DataExchange targets reference TKV3d, TKCAF, ...), so the libraries we
# use are found directly. Sets OCCT_INCLUDE_DIR and the library lists below;
# the include directory is given only to the sources in framework/geometry/occ.
find_path(OCCT_INCLUDE_DIR Standard_Version.hxx PATH_SUFFIXES opencascade REQUIRED)
# OCCT_LIBRARIES: what the framework links. The toolkits only some runs
# need are linked by modules the framework opens on first use
# (framework/core/lazy_module.h): OCCT_STEP_LIBRARIES, OCCT_IGES_LIBRARIES
# and OCCT_LOFT_LIBRARIES (ThruSections; TKOffset brings TKFillet and
# TKBool). OCCT_TEST_LIBRARIES: the modelling toolkits tests use directly
# (a fillet).
set(OCCT_LIBRARIES "")
foreach(_lib TKShHealing TKBO TKPrim TKTopAlgo TKGeomAlgo TKBRep TKGeomBase TKG3d TKG2d
             TKMath TKernel)
  find_library(OCCT_${_lib}_LIBRARY ${_lib} REQUIRED)
  list(APPEND OCCT_LIBRARIES ${OCCT_${_lib}_LIBRARY})
endforeach()
set(OCCT_STEP_LIBRARIES "")
foreach(_lib TKSTEP TKSTEPAttr TKSTEP209 TKSTEPBase TKXSBase)
  find_library(OCCT_${_lib}_LIBRARY ${_lib} REQUIRED)
  list(APPEND OCCT_STEP_LIBRARIES ${OCCT_${_lib}_LIBRARY})
endforeach()
find_library(OCCT_TKIGES_LIBRARY TKIGES REQUIRED)
set(OCCT_IGES_LIBRARIES ${OCCT_TKIGES_LIBRARY} ${OCCT_TKXSBase_LIBRARY})
find_library(OCCT_TKOffset_LIBRARY TKOffset REQUIRED)
set(OCCT_LOFT_LIBRARIES ${OCCT_TKOffset_LIBRARY})
set(OCCT_TEST_LIBRARIES "")
foreach(_lib TKFillet TKBool TKOffset)
  find_library(OCCT_${_lib}_LIBRARY ${_lib} REQUIRED)
  list(APPEND OCCT_TEST_LIBRARIES ${OCCT_${_lib}_LIBRARY})
endforeach()
list(APPEND OCCT_TEST_LIBRARIES ${OCCT_LIBRARIES})
message(STATUS "OpenCASCADE: ${OCCT_INCLUDE_DIR}")
