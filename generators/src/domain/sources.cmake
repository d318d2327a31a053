# Sources of generators/src/domain (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/domain_problem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domain_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domain_validation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domain_mesh_data.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curves_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/default_domains.cpp
  ${CMAKE_CURRENT_LIST_DIR}/constructive_geometry_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/exact_snap.cpp
  ${CMAKE_CURRENT_LIST_DIR}/convex_hull_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_validation_3.cpp
)
