# Interoperability with Gmsh and meshio (interop_test.py): each test converts with the certimesh
# CLI and compares with what the other tool reads or writes. A test whose tool is absent exits
# 77 and CTest reports it as skipped (with the reason in its output).
# meshio is Debian's python3-meshio: /usr/bin/python3 first (design README, decision 7).
find_program(CERTIMESH_IO_INTEROP_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(CERTIMESH_IO_INTEROP_PYTHON NAMES python3)
set(_interop_script ${CMAKE_CURRENT_SOURCE_DIR}/interop_test.py)
foreach(_interop gmsh_reads_certimesh certimesh_reads_gmsh meshio_reads_certimesh certimesh_reads_meshio)
  add_test(NAME io.interop_${_interop}
           COMMAND ${CERTIMESH_IO_INTEROP_PYTHON} ${_interop_script} ${_interop} $<TARGET_FILE:certimesh>
                   ${CMAKE_CURRENT_BINARY_DIR}/interop/${_interop} ${CMAKE_CURRENT_SOURCE_DIR}/data/gmsh)
  set_tests_properties(io.interop_${_interop} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS "io;interop")
endforeach()
# The surface readers (.off, ASCII/binary .stl, .mesh) against meshio as writer and reader.
add_test(NAME io.surface_meshio
         COMMAND ${CERTIMESH_IO_INTEROP_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/surface_meshio_test.py $<TARGET_FILE:certimesh>
                 ${CMAKE_CURRENT_BINARY_DIR}/interop/surface_meshio)
set_tests_properties(io.surface_meshio PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS "io;interop")
