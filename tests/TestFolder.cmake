# certimesh_test_folder(PART): every *_test.cpp in the calling folder becomes one GoogleTest
# executable "<PART>_<name>", linked with certimesh::<PART>, the readers, the predicates, the
# rational oracle, the fuzz generators and RapidCheck; its CTest names start with "<PART>.".
# Tests that need CGAL as an oracle are named *_cgal_test.cpp and call it through
# tests/support/cgal_reference.h (CGAL compiles slowly: its code is compiled once, in the
# certimesh_cgal_reference library of tests/CMakeLists.txt; a test file includes no CGAL header). Extra, non-GoogleTest tests (scripts) go in
# tests.cmake beside the folder's CMakeLists.txt.
include(GoogleTest)

# Two switches for the suite's own build time (scripts/test.sh sets them; a developer's
# ccache build keeps the defaults, as ccache does not cache precompiled headers):
#   CERTIMESH_TEST_PCH          the GoogleTest and RapidCheck headers are precompiled once
#                               and reused by every test file (about 3 s less per file)
#   CERTIMESH_CGAL_ORACLE_TESTS the *_cgal_test.cpp files (the slowest to compile); the
#                               sanitizer stage leaves them out, stage 1 runs them
option(CERTIMESH_TEST_PCH "Precompile the test framework headers once for all tests" OFF)
option(CERTIMESH_CGAL_ORACLE_TESTS "Build the tests that use CGAL as an oracle" ON)
# A test file is compile-bound, not run-bound: the libraries it calls keep the build type's
# optimization, the file itself is built at -O1 in Release (a third less compile time than -O3
# for the RapidCheck-heavy files) and at -O0 under the sanitizers (half the compile time of
# -O1 there: 24 s against 55 s for io/triangle_roundtrip_test.cpp; the sanitizers' checks are
# the same, and the code under test runs at -O1). The precompiled header gets the same flags.
function(certimesh_test_optimization target)
  if(CERTIMESH_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
  elseif(CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()

if(CERTIMESH_TEST_PCH AND NOT TARGET certimesh_test_pch)
  # An executable, not an object library: the header must be compiled with the tests' own
  # -fPIE (an object library gets -fPIC, and GCC then ignores the precompiled header).
  file(WRITE ${CMAKE_BINARY_DIR}/certimesh_test_pch.cpp "int main() { return 0; }\n")
  add_executable(certimesh_test_pch ${CMAKE_BINARY_DIR}/certimesh_test_pch.cpp)
  target_link_libraries(certimesh_test_pch PRIVATE rapidcheck_gtest GTest::gtest)
  # The frameworks and the standard headers most test files include (parsing is about half
  # of a test file's compile time without them).
  target_precompile_headers(certimesh_test_pch PRIVATE <gtest/gtest.h> <rapidcheck.h> <rapidcheck/gtest.h>
    <algorithm> <array> <cmath> <cstdint> <cstdlib> <cstring> <filesystem> <fstream> <functional>
    <limits> <map> <memory> <optional> <random> <set> <span> <sstream> <string> <vector>)
  certimesh_warnings(certimesh_test_pch)
  certimesh_test_optimization(certimesh_test_pch)
endif()

function(certimesh_test_folder part)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  foreach(source IN LISTS sources)
    get_filename_component(name ${source} NAME_WE)
    if(name MATCHES "_cgal_test$" AND NOT CERTIMESH_CGAL_ORACLE_TESTS)
      continue()
    endif()
    set(target ${part}_${name})
    add_executable(${target} ${source})
    target_link_libraries(${target} PRIVATE certimesh::${part} certimesh::io certimesh::predicates
                          certimesh_test_oracle certimesh_fuzz_generators rapidcheck_gtest
                          certimesh_test_main)
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_definitions(${target} PRIVATE
      CERTIMESH_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}"
      CERTIMESH_CLI="$<TARGET_FILE:certimesh>")
    if(name MATCHES "_cgal_test$")
      target_link_libraries(${target} PRIVATE certimesh_cgal_reference)
    endif()
    certimesh_warnings(${target})
    certimesh_test_optimization(${target})
    if(CERTIMESH_TEST_PCH)
      target_precompile_headers(${target} REUSE_FROM certimesh_test_pch)
      # A header GCC cannot use (other flags) is only slower: say so, do not fail.
      target_compile_options(${target} PRIVATE -Winvalid-pch -Wno-error=invalid-pch)
    endif()
    gtest_discover_tests(${target} TEST_PREFIX "${part}." DISCOVERY_TIMEOUT 120)
  endforeach()
endfunction()
