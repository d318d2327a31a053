# Sources of generators/src/pipeline_3 (included by generators/CMakeLists.txt): the 3D meshing
# pipeline of mesh_solid_3.h, one stage per file.
target_sources(certimesh_generators PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/mesh_solid_3.cpp
)
