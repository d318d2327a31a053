#!/usr/bin/env bash
# The test suite, as CI runs it (.ci/run calls exactly this):
#   1. build/       : configure with warnings as errors, build everything, ctest
#   2. build-asan/  : the same suite built and run once more under AddressSanitizer and
#                     UndefinedBehaviorSanitizer (benchmarks and the CGAL oracle tests
#                     off; tests labelled `slow`,
#                     `no-sanitize` or `proofs` (Gappa/Coq: no certimesh code runs) are left
#                     out, see CERTIMESH_ASAN_EXCLUDE below)
# Stops at the first failing stage; the exit status is that stage's. ctest's summary is the
# last thing printed. Environment: CERTIMESH_JOBS (default: nproc), CERTIMESH_SKIP_ASAN=1
# to run stage 1 only, CERTIMESH_ASAN_EXCLUDE (a ctest label regex), CERTIMESH_BUILD_DIR and
# CERTIMESH_ASAN_BUILD_DIR (default build, build-asan), CERTIMESH_TEST_MEMORY_MB (per test
# process memory cap, default 6144: a runaway test fails alone instead of exhausting a
# shared machine; stage 1 through ulimit -v, stage 2 through the sanitizers' RSS limit),
# CERTIMESH_CTEST_ARGS (extra ctest arguments for both stages, e.g. "-R packaging").
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

bash scripts/install-deps.sh
jobs=${CERTIMESH_JOBS:-$(nproc)}
build=${CERTIMESH_BUILD_DIR:-build}
asan=${CERTIMESH_ASAN_BUILD_DIR:-build-asan}
memory_mb=${CERTIMESH_TEST_MEMORY_MB:-6144}
read -r -a extra_ctest_args <<<"${CERTIMESH_CTEST_ARGS:-}"
stamp() { echo "== $(date -u +%H:%M:%S) $*"; }
stage1_ctest() {
  ulimit -v $((memory_mb * 1024))
  exec ctest --test-dir "$build" --output-on-failure -j"$jobs" "${extra_ctest_args[@]}"
}

# The suite's build is most of its time: test headers precompiled once, and lld to link
# (tests/TestFolder.cmake; a developer's own build keeps ccache-friendly defaults).
speed=(-DCERTIMESH_TEST_PCH=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld)

stamp "stage 1: $build/ (Release, -Werror)"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCERTIMESH_WERROR=ON "${speed[@]}"
cmake --build "$build" -j"$jobs"
stamp "stage 1: ctest"
if [[ "${CERTIMESH_SKIP_ASAN:-0}" == 1 ]]; then
  stage1_ctest
fi
(stage1_ctest)

stamp "stage 2: $asan/ (ASan + UBSan)"
# -O1 -g1 (line tables are all the sanitizers' stack traces need): under the sanitizers it
# compiles in half the CPU time of RelWithDebInfo's -O2 -g (60 s against 134 s for the
# heaviest test file), and the build is most of this stage's time.
# The CGAL oracle tests are left out here: they are the slowest files to compile (a quarter
# of this stage's build) and compare with CGAL what stage 1 compared; the code they call runs
# under the sanitizers in the other tests.
# The libraries build as unity translation units here (CERTIMESH_UNITY_LIBRARIES; stage 1
# keeps the per-file build a developer has).
cmake -S . -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCERTIMESH_SANITIZE=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCERTIMESH_BUILD_BENCHMARKS=OFF \
      -DCERTIMESH_CGAL_ORACLE_TESTS=OFF -DCERTIMESH_UNITY_LIBRARIES=ON "${speed[@]}"
cmake --build "$asan" -j"$jobs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_string_checks=1:hard_rss_limit_mb=$memory_mb}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# The predicate properties run a tenth of their cases here (the full counts ran in stage 1;
# this stage is for memory errors and undefined behaviour, 5-10x slower per case): 2,500 per
# property, 49 s for the 84 predicate tests on 2 cores against 116 s at a quarter.
export CERTIMESH_RC_SCALE=${CERTIMESH_RC_SCALE:-0.1}
stamp "stage 2: ctest under sanitizers"
exec ctest --test-dir "$asan" --output-on-failure -j"$jobs" \
     --label-exclude "${CERTIMESH_ASAN_EXCLUDE:-^(slow|no-sanitize|proofs)$}" "${extra_ctest_args[@]}"
