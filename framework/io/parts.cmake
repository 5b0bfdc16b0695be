# io has three independent parts: the journal reader (this folder), the mesh
# exporters (export/) and the mesh file readers (read/).
foreach(part journal_parts.cmake export/parts.cmake read/parts.cmake)
  if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/${part})
    include(${CMAKE_CURRENT_LIST_DIR}/${part})
  endif()
endforeach()
