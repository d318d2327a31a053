# Sources of generators/src/domain (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/placeholder_domain.cpp
)
