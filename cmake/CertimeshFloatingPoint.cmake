# The floating-point environment the filter proofs assume (proofs/README.md):
# IEEE binary64, round to nearest, no contraction of a*b+c into FMA, no excess precision,
# no fast-math. Applied to every translation unit of the predicate kernel; the test
# tests/predicates/fp_environment_test.cpp and the object-code scan in tests/CMakeLists.txt
# check that the built kernel honours it.
# (Excess precision cannot occur on x86-64/aarch64, which evaluate double in binary64;
# detail/fp_requirements.h and the run-time probe check FLT_EVAL_METHOD == 0.)
set(CERTIMESH_KERNEL_FP_FLAGS -ffp-contract=off -frounding-math -fno-fast-math)
function(certimesh_kernel_fp target)
  target_compile_options(${target} PRIVATE ${CERTIMESH_KERNEL_FP_FLAGS})
endfunction()
