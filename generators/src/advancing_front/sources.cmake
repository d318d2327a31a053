# Sources of generators/src/advancing_front (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/placeholder_advancing_front.cpp
)
