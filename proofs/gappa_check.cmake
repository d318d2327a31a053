# cmake -DGAPPA=... -DSCRIPT=<file.g> [-DCOQ_OUT=<file.v>] -P gappa_check.cmake
# Has gappa prove every goal of SCRIPT; with COQ_OUT, gappa also writes the Coq certificate
# of the proof there (one proof search serves both checks: proofs.coq.<script> only runs
# coqc on it). Fails on a non-zero exit, an "Error" line, or the warning for a rewriting
# hint that is not an identity (gappa would still apply it).
set(backend)
set(output_args)
if(COQ_OUT)
  get_filename_component(out_dir "${COQ_OUT}" DIRECTORY)
  file(MAKE_DIRECTORY "${out_dir}")
  file(REMOVE "${COQ_OUT}")
  set(backend -Bcoq)
  set(output_args OUTPUT_FILE "${COQ_OUT}.partial")
endif()
execute_process(COMMAND "${GAPPA}" ${backend} "${SCRIPT}" ${output_args}
                ERROR_VARIABLE gappa_err RESULT_VARIABLE rc)
message("${gappa_err}")
if(NOT rc EQUAL 0 OR gappa_err MATCHES "Error|not trivially equal")
  message(FATAL_ERROR "gappa ${SCRIPT} did not prove every goal (${rc})")
endif()
if(COQ_OUT)
  # Renamed only once complete: a failed or interrupted run leaves no certificate behind.
  file(RENAME "${COQ_OUT}.partial" "${COQ_OUT}")
endif()
