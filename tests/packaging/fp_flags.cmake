# cmake -DCXX=<compiler> -DINCLUDE=<predicates/include> -DWORK=<dir> -P fp_flags.cmake
# What the predicate headers do under a consumer's floating-point flags
# (detail/fp_requirements.h): -ffast-math and -Ofast are refused with the header's message;
# flags under which inline filters could be rewritten route them out of line; baseline
# flags keep them inline. Each case compiles a one-line file with -fsyntax-only.
file(MAKE_DIRECTORY "${WORK}")
set(_src "${WORK}/fp_flags_probe.cpp")
file(WRITE "${_src}" "#include <certimesh/predicates/insphere.h>
#include <certimesh/predicates/orient3d.h>
static_assert(CERTIMESH_FILTERS_OUT_OF_LINE == EXPECTED_ROUTE, \"unexpected filter route\");
")
execute_process(COMMAND "${CXX}" --version OUTPUT_VARIABLE _version)
string(REGEX MATCH "clang" _is_clang "${_version}")

# Returns in ${out} the compiler's exit status and appends its output to ${log}.
function(compile flags route out log)
  separate_arguments(_flags UNIX_COMMAND "${flags}")
  execute_process(COMMAND "${CXX}" -std=c++20 -fsyntax-only ${_flags} -DEXPECTED_ROUTE=${route}
                          -I "${INCLUDE}" "${_src}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(${out} ${rc} PARENT_SCOPE)
  set(${log} "${o}${e}" PARENT_SCOPE)
endfunction()

set(_failures "")
set(_refusal "do not compile code that includes them with -ffast-math")
foreach(flags "-ffast-math" "-Ofast" "-O2 -ffast-math -march=haswell")
  compile("${flags}" 0 rc log)
  if(rc EQUAL 0 OR NOT log MATCHES "${_refusal}")
    string(APPEND _failures "\n${flags}: not refused with the message (exit ${rc}):\n${log}")
  endif()
endforeach()

set(_out_of_line "-march=haswell" "-mfma" "-mfma4" "-march=haswell -ffp-contract=fast"
                 "-ffinite-math-only" "-DCERTIMESH_FILTERS_ALWAYS_OUT_OF_LINE")
if(NOT _is_clang)  # GCC only: clang has no x87 mode on x86-64 nor a reassociation macro
  list(APPEND _out_of_line "-mfpmath=387" "-fassociative-math -fno-signed-zeros -fno-trapping-math")
endif()
set(_inline "-O2" "-O3 -ffp-contract=fast" "-O2 -march=x86-64-v2")
foreach(route 1 0)
  set(_cases ${_out_of_line})
  if(route EQUAL 0)
    set(_cases ${_inline})
  endif()
  foreach(flags IN LISTS _cases)
    compile("${flags}" ${route} rc log)
    if(NOT rc EQUAL 0)
      string(APPEND _failures "\n${flags}: expected route ${route} (1 = out of line):\n${log}")
    endif()
  endforeach()
endforeach()

if(_failures)
  message(FATAL_ERROR "fp_flags with ${CXX}:${_failures}")
endif()
message(STATUS "fp_flags with ${CXX}: refusals and routes as documented")
