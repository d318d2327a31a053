# Sources of generators/src/advancing_front (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/advancing_front_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/front_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/front_grid_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/front_measure_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/front_sizing_2.cpp
)
