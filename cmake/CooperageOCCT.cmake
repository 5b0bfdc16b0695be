# OpenCASCADE 7.6 from Debian's libocct-*-dev. Debian's OpenCASCADEConfig.cmake
# refuses to load unless the visualisation and OCAF modules are installed too
# (its DataExchange targets reference TKV3d, TKCAF, ...), so the libraries we
# use are found directly. Sets OCCT_INCLUDE_DIR, OCCT_LIBRARIES and
# OCCT_EXCHANGE_LIBRARIES; the include
# directory is given only to the sources in framework/geometry/occ.
find_path(OCCT_INCLUDE_DIR Standard_Version.hxx PATH_SUFFIXES opencascade REQUIRED)
# OCCT_EXCHANGE_LIBRARIES: the STEP/IGES toolkits, linked only by the
# exchange module that framework/geometry/occ loads on first use.
set(OCCT_LIBRARIES "")
foreach(_lib TKShHealing TKFillet TKOffset TKFeat TKBool TKBO TKPrim TKMesh TKTopAlgo
             TKGeomAlgo TKBRep TKGeomBase TKG3d TKG2d TKMath TKernel)
  find_library(OCCT_${_lib}_LIBRARY ${_lib} REQUIRED)
  list(APPEND OCCT_LIBRARIES ${OCCT_${_lib}_LIBRARY})
endforeach()
set(OCCT_EXCHANGE_LIBRARIES "")
foreach(_lib TKSTEP TKSTEPAttr TKSTEP209 TKSTEPBase TKIGES TKXSBase)
  find_library(OCCT_${_lib}_LIBRARY ${_lib} REQUIRED)
  list(APPEND OCCT_EXCHANGE_LIBRARIES ${OCCT_${_lib}_LIBRARY})
endforeach()
message(STATUS "OpenCASCADE: ${OCCT_INCLUDE_DIR}")
