# bench_delaunay_3d: Delaunay3 against CGAL's Delaunay_triangulation_3 on 10^6 uniform points
# and the 40^3 grid (checked run). CGAL lives in its own translation unit (-frounding-math).
add_library(certimesh_bench_delaunay_3d_cgal OBJECT bench_delaunay_3d_cgal.cpp)
target_link_libraries(certimesh_bench_delaunay_3d_cgal PRIVATE CGAL::CGAL)
certimesh_warnings(certimesh_bench_delaunay_3d_cgal)

add_executable(bench_delaunay_3d bench_delaunay_3d.cpp)
target_link_libraries(bench_delaunay_3d PRIVATE certimesh_bench_delaunay_3d_cgal certimesh::generators
                                                CGAL::CGAL benchmark::benchmark)
certimesh_warnings(bench_delaunay_3d)
if(CERTIMESH_BUILD_TESTS)
  add_test(NAME bench.delaunay_3d_smoke COMMAND bench_delaunay_3d --dt_small --benchmark_min_time=0.01)
  set_tests_properties(bench.delaunay_3d_smoke PROPERTIES TIMEOUT 60 LABELS bench)
endif()
