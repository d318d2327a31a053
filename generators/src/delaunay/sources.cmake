# Sources of generators/src/delaunay (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/placeholder_delaunay.cpp
)
