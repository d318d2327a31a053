# Meshes written by Gmsh, certified by the CLI with and without --boundary-tolerance
# (peer_meshes_test.py; skipped, exit 77, when gmsh is absent).
find_program(CERTIMESH_CERT_PYTHON NAMES python3)
add_test(NAME certificate.peer_meshes_gmsh
         COMMAND ${CERTIMESH_CERT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/peer_meshes_test.py $<TARGET_FILE:certimesh>
                 ${CMAKE_CURRENT_BINARY_DIR}/peer_meshes)
set_tests_properties(certificate.peer_meshes_gmsh PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120 LABELS "certificate;interop")
# `certimesh mesh` on 2D domains with pinch vertices, certified (pinch_cli_test.py).
add_test(NAME certificate.pinch_cli
         COMMAND ${CERTIMESH_CERT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/pinch_cli_test.py $<TARGET_FILE:certimesh>
                 ${CMAKE_CURRENT_BINARY_DIR}/pinch_cli)
set_tests_properties(certificate.pinch_cli PROPERTIES TIMEOUT 120 LABELS "certificate;cli")
# TetGen's .poly domains (polygonal facets, facet holes, cavities, regions, an internal facet)
# meshed by TetGen and certified, and TetGen's meshes broken on purpose refused
# (tetgen_domains_test.py; skipped, exit 77, when tetgen is absent).
add_test(NAME certificate.tetgen_domains
         COMMAND ${CERTIMESH_CERT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/tetgen_domains_test.py $<TARGET_FILE:certimesh>
                 ${CMAKE_CURRENT_BINARY_DIR}/tetgen_domains)
set_tests_properties(certificate.tetgen_domains PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120 LABELS "certificate;interop")
# exact_sum_test reads a header internal to certificate/ (its fixed-width and GMP paths).
target_include_directories(certificate_exact_sum_test PRIVATE ${PROJECT_SOURCE_DIR}/certificate/src)
target_include_directories(certificate_worst_case_shapes_test PRIVATE ${PROJECT_SOURCE_DIR}/certificate/src)
