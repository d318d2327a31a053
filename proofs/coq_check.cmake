# cmake -DCOQC=... -DCERTIFICATE=<file.v> -P coq_check.cmake
# Has coqc check the Coq certificate that proofs.gappa.<script> had gappa write (its
# fixture). Fails if the file is missing or coqc rejects it.
if(NOT EXISTS "${CERTIFICATE}")
  message(FATAL_ERROR "no Coq certificate ${CERTIFICATE}: proofs.gappa.* did not write it")
endif()
get_filename_component(dir "${CERTIFICATE}" DIRECTORY)
get_filename_component(file "${CERTIFICATE}" NAME)
execute_process(COMMAND "${COQC}" "${file}" WORKING_DIRECTORY "${dir}"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "coqc rejected ${CERTIFICATE} (${rc}):\n${out}\n${err}")
endif()
message(STATUS "coqc accepted ${CERTIFICATE}")
