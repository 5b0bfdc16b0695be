# The XML journal reader (docs/journal.md): journal -> io::Job.
cooperage_framework_part(io_journal
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/journal_reader.cpp
    ${CMAKE_CURRENT_LIST_DIR}/journal_geometry.cpp
    ${CMAKE_CURRENT_LIST_DIR}/journal_mesh.cpp
    ${CMAKE_CURRENT_LIST_DIR}/journal_groups.cpp
    ${CMAKE_CURRENT_LIST_DIR}/journal_xml.cpp
    ${CMAKE_CURRENT_LIST_DIR}/element_size.cpp
  PRIVATE_DEPS tinyxml2::tinyxml2)
