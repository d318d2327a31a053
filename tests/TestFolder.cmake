# certimesh_test_folder(PART): every *_test.cpp in the calling folder becomes one GoogleTest
# executable "<PART>_<name>", linked with certimesh::<PART>, the readers, the predicates, the
# rational oracle, the fuzz generators and RapidCheck; its CTest names start with "<PART>.".
# Tests that need CGAL as an oracle are named *_cgal_test.cpp (CGAL compiles slowly: keep it in
# as few translation units as possible). Extra, non-GoogleTest tests (scripts) go in
# tests.cmake beside the folder's CMakeLists.txt.
include(GoogleTest)

function(certimesh_test_folder part)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  foreach(source IN LISTS sources)
    get_filename_component(name ${source} NAME_WE)
    set(target ${part}_${name})
    add_executable(${target} ${source})
    target_link_libraries(${target} PRIVATE certimesh::${part} certimesh::io certimesh::predicates
                          certimesh_test_oracle certimesh_fuzz_generators rapidcheck_gtest
                          GTest::gtest_main)
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_definitions(${target} PRIVATE
      CERTIMESH_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}"
      CERTIMESH_CLI="$<TARGET_FILE:certimesh>")
    if(name MATCHES "_cgal_test$")
      find_package(CGAL REQUIRED)
      pkg_check_modules(MPFR REQUIRED IMPORTED_TARGET mpfr)
      target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::MPFR)
    endif()
    certimesh_warnings(${target})
    # A test file is compile-bound, not run-bound: the libraries it calls keep the build
    # type's optimization, the file itself is built at -O1 (a third less compile time than
    # -O3 for the RapidCheck-heavy files; the suite's build is most of its time).
    if(CMAKE_BUILD_TYPE STREQUAL "Release")
      target_compile_options(${target} PRIVATE -O1)
    endif()
    gtest_discover_tests(${target} TEST_PREFIX "${part}." DISCOVERY_TIMEOUT 120)
  endforeach()
endfunction()
