# cmake -DGAPPA=... -DCOQC=... -DSCRIPT=<file.g> -DOUT_DIR=<dir> -P coq_check.cmake
# Has gappa emit the Coq certificate of SCRIPT, then has coqc check it. Fails if either fails.
get_filename_component(name "${SCRIPT}" NAME_WE)
file(MAKE_DIRECTORY "${OUT_DIR}")
set(v "${OUT_DIR}/${name}.v")
execute_process(COMMAND "${GAPPA}" -Bcoq "${SCRIPT}"
                OUTPUT_FILE "${v}" ERROR_VARIABLE gappa_err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR gappa_err MATCHES "Error")
  message(FATAL_ERROR "gappa -Bcoq ${SCRIPT} failed (${rc}):\n${gappa_err}")
endif()
execute_process(COMMAND "${COQC}" "${name}.v" WORKING_DIRECTORY "${OUT_DIR}"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "coqc rejected the certificate of ${SCRIPT} (${rc}):\n${out}\n${err}")
endif()
message(STATUS "coqc accepted the certificate of ${SCRIPT}")
