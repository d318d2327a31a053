# experiment_regrade_2d: the §5.2 regrading experiment of the local modifications (square with
# two holes, ~1,800 triangles, three operation sets) beside the monograph's numbers.
add_executable(experiment_regrade_2d experiment_regrade_2d.cpp)
target_link_libraries(experiment_regrade_2d PRIVATE certimesh::generators certimesh::certificate
                                                    certimesh::topology certimesh::io)
# point_on_segment (the rounding of an exact point of a segment) is the pipeline's own helper:
# boundary splits in the experiment put their vertex exactly where the pipeline would.
target_include_directories(experiment_regrade_2d PRIVATE ${PROJECT_SOURCE_DIR}/generators/src/pipeline)
certimesh_warnings(experiment_regrade_2d)
if(CERTIMESH_BUILD_TESTS)
  add_test(NAME bench.regrade_2d_smoke COMMAND experiment_regrade_2d --max-operations 3000)
  set_tests_properties(bench.regrade_2d_smoke PROPERTIES TIMEOUT 60 LABELS bench)
endif()
