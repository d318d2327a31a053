# Sources of generators/src/improvement (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/quality_order.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quality_improvement_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quality_improvement_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_segments_2.cpp
)
