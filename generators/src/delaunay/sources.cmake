# Sources of generators/src/delaunay (included by generators/CMakeLists.txt).
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/hilbert_order.cpp
  ${CMAKE_CURRENT_LIST_DIR}/large_array.cpp
  ${CMAKE_CURRENT_LIST_DIR}/constrained_delaunay_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/delaunay_refinement_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/quality_refinement_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_set_2.cpp
  ${CMAKE_CURRENT_LIST_DIR}/delaunay_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_set_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/refinement_mesh_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tetrahedral_refinement_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/recovery_flips_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/recovery_mesh_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/edge_recovery_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/face_recovery_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_classification_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solid_regions_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/steiner_removal_3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/boundary_recovery_3.cpp
)
