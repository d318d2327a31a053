# bench_sos_2d: the GMP-free perturbed signs of orient2d / incircle against the generic
# GMP monomial search, on every degenerate tuple of a small integer grid.
add_executable(bench_sos_2d bench_sos_2d.cpp)
target_link_libraries(bench_sos_2d PRIVATE certimesh::predicates benchmark::benchmark)
certimesh_warnings(bench_sos_2d)
if(CERTIMESH_BUILD_TESTS)
  add_test(NAME bench.sos_2d_smoke COMMAND bench_sos_2d --benchmark_min_time=0.01)
  set_tests_properties(bench.sos_2d_smoke PROPERTIES TIMEOUT 60 LABELS bench)
endif()
