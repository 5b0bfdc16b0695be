# framework/report: the self-contained HTML report of a mesh (pictures,
# quality histograms, plan, time per stage), shared by the CLI, journals and
# the Python package.
cooperage_framework_part(report SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/colormap.cpp
  ${CMAKE_CURRENT_LIST_DIR}/simplify_faces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_pictures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/html_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/html_figures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/viewer_script.cpp
  ${CMAKE_CURRENT_LIST_DIR}/html_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report_from_run.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report_from_file.cpp)
