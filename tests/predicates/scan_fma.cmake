# cmake -DLIBRARY=<path> [-DMIN_INSTRUCTIONS=n] [-DEXPECT_FMA=ON] -P scan_fma.cmake
# Fails when the disassembly of LIBRARY contains a fused multiply-add: contraction would
# break the error-free transformations and the proven filter bounds. Also used on the
# object code a consumer inlines (tests/packaging/fp_consumer), which is smaller
# (MIN_INSTRUCTIONS), and on a canary that must contain one (EXPECT_FMA), so that a clean
# scan cannot come from a pattern this toolchain's objdump never prints.
if(NOT DEFINED MIN_INSTRUCTIONS)
  set(MIN_INSTRUCTIONS 100)
endif()
if(NOT LIBRARY OR NOT EXISTS "${LIBRARY}")
  message(FATAL_ERROR "scan_fma: LIBRARY='${LIBRARY}' does not exist")
endif()
find_program(OBJDUMP NAMES objdump llvm-objdump REQUIRED)
execute_process(COMMAND ${OBJDUMP} -d --no-show-raw-insn "${LIBRARY}"
                OUTPUT_VARIABLE disasm RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "scan_fma: objdump failed (${rc}): ${err}")
endif()
string(LENGTH "${disasm}" n)
string(REGEX MATCHALL "[^\n]*\t(vfmadd|vfmsub|vfnmadd|vfnmsub|fmadd|fmsub|fnmadd|fnmsub)[0-9a-z]*[ \t][^\n]*" hits "${disasm}")
# A disassembly without any instruction would make the scan vacuous.
string(REGEX MATCHALL "\n[ \t]*[0-9a-f]+:\t" insns "${disasm}")
list(LENGTH insns ninsn)
if(ninsn LESS MIN_INSTRUCTIONS)
  message(FATAL_ERROR "scan_fma: only ${ninsn} instructions disassembled from ${LIBRARY}")
endif()
list(LENGTH hits nhits)
if(EXPECT_FMA)
  if(nhits EQUAL 0)
    message(FATAL_ERROR "scan_fma: no FMA found in ${LIBRARY}, which must contain one")
  endif()
  message(STATUS "scan_fma: ${nhits} FMA instruction(s) in ${LIBRARY}, as expected")
  return()
endif()
if(nhits GREATER 0)
  list(SUBLIST hits 0 20 shown)
  string(REPLACE ";" "\n" shown "${shown}")
  message(FATAL_ERROR "scan_fma: ${nhits} FMA instruction(s) in ${LIBRARY}:\n${shown}")
endif()
message(STATUS "scan_fma: ${ninsn} instructions, no FMA in ${LIBRARY}")
