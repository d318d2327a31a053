# Sources of generators/src/pipeline (included by generators/CMakeLists.txt): the 2D meshing
# pipeline of mesh_domain_2.h, one stage per file.
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/point_on_segment.cpp
  ${CMAKE_CURRENT_LIST_DIR}/boundary_discretization.cpp
  ${CMAKE_CURRENT_LIST_DIR}/boundary_size_field.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domain_triangulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/delaunay_completion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/region_labels.cpp
  ${CMAKE_CURRENT_LIST_DIR}/refinement_stage.cpp
  ${CMAKE_CURRENT_LIST_DIR}/improvement_region.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vertex_smoothing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/isolated_vertices.cpp
  ${CMAKE_CURRENT_LIST_DIR}/area_bound.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_domain_2.cpp
)
