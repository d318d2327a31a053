# bench_mesh_2d: Table 3.1 (unit square, quasi-uniform h) with certimesh's 2D pipeline beside
# `gmsh -2 -algo front2d` in the same run (bench/RESULTS.md, "bench_mesh_2d").
add_executable(bench_mesh_2d bench_mesh_2d.cpp)
target_link_libraries(bench_mesh_2d PRIVATE certimesh::generators certimesh::certificate certimesh::topology
                                            certimesh::io)
certimesh_warnings(bench_mesh_2d)
if(CERTIMESH_BUILD_TESTS)
  add_test(NAME bench.mesh_2d_smoke COMMAND bench_mesh_2d --sizes 0.05 --repetitions 1 --gmsh none)
  set_tests_properties(bench.mesh_2d_smoke PROPERTIES TIMEOUT 60 LABELS bench)
endif()
