# bench_delaunay_2d: ConstrainedDelaunay2 against CGAL's Delaunay_triangulation_2 on 10^6
# uniform points, the 1000 x 1000 grid (checked run) and 10^5 points on a circle (checked
# run). CGAL lives in its own translation unit (it needs -frounding-math).
add_library(certimesh_bench_delaunay_cgal OBJECT bench_delaunay_2d_cgal.cpp)
target_link_libraries(certimesh_bench_delaunay_cgal PRIVATE CGAL::CGAL)
certimesh_warnings(certimesh_bench_delaunay_cgal)

add_executable(bench_delaunay_2d bench_delaunay_2d.cpp)
target_link_libraries(bench_delaunay_2d PRIVATE certimesh_bench_delaunay_cgal certimesh::generators
                                                CGAL::CGAL benchmark::benchmark)
certimesh_warnings(bench_delaunay_2d)
if(CERTIMESH_BUILD_TESTS)
  add_test(NAME bench.delaunay_2d_smoke COMMAND bench_delaunay_2d --dt_small --benchmark_min_time=0.01)
  set_tests_properties(bench.delaunay_2d_smoke PROPERTIES TIMEOUT 60 LABELS bench)
endif()
