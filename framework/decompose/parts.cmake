cooperage_framework_part(decompose SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/surface_fit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/volume_samples.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cut_surface.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cut_candidates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cone_candidates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/piece_verdict.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cut_score.cpp
  ${CMAKE_CURRENT_LIST_DIR}/part_ids.cpp
  ${CMAKE_CURRENT_LIST_DIR}/search_cuts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/same_part.cpp
  ${CMAKE_CURRENT_LIST_DIR}/decompose.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report_text.cpp)
