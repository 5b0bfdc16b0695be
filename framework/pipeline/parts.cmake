cooperage_framework_part(pipeline SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/build_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/decomposed_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/check_settings.cpp
  ${CMAKE_CURRENT_LIST_DIR}/interval_setup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_curves.cpp
  ${CMAKE_CURRENT_LIST_DIR}/commit_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quality_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/worst_element.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_size.cpp
  ${CMAKE_CURRENT_LIST_DIR}/measure_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/partial_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/finer_retry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesher.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model_job.cpp
  ${CMAKE_CURRENT_LIST_DIR}/relative_size.cpp
  PRIVATE_DEPS TBB::tbb)
