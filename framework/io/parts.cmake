# io has two independent parts: the journal reader (this folder) and the
# mesh exporters (export/).
foreach(part journal_parts.cmake export/parts.cmake)
  if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/${part})
    include(${CMAKE_CURRENT_LIST_DIR}/${part})
  endif()
endforeach()
