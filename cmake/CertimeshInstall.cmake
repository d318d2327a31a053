# Installation: the library, its headers, the CLI (tools/certimesh installs itself), the CMake
# package (certimeshConfig.cmake, certimeshConfigVersion.cmake, certimeshTargets.cmake with
# namespaced targets certimesh::...) and the pkg-config file certimesh.pc.
#
# GMP is a PRIVATE dependency of certimesh_predicates: no public header includes it. A static
# archive cannot carry it, so the exported target still names it as $<LINK_ONLY:PkgConfig::GMP>;
# certimeshConfig.cmake recreates that target on the consumer side (pkg-config, else
# find_library), and certimesh.pc lists it for the linker.
include(CMakePackageConfigHelpers)

set(CERTIMESH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/certimesh
    CACHE STRING "Where certimeshConfig.cmake is installed, relative to the prefix")
set(CERTIMESH_INSTALL_PKGCONFIGDIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig
    CACHE STRING "Where certimesh.pc is installed, relative to the prefix")

# The libraries, in dependency order: predicates <- io <- topology <- generators; certificate.
set(CERTIMESH_INSTALLED_LIBRARIES certimesh_predicates certimesh_io certimesh_topology
                                  certimesh_certificate certimesh_generators)
install(TARGETS ${CERTIMESH_INSTALLED_LIBRARIES}
        EXPORT certimeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(part predicates io topology certificate generators)
  if(EXISTS ${PROJECT_SOURCE_DIR}/${part}/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part}/include/
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
            FILES_MATCHING PATTERN "*.h")
  endif()
endforeach()

install(EXPORT certimeshTargets
        NAMESPACE certimesh::
        FILE certimeshTargets.cmake
        DESTINATION ${CERTIMESH_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/certimeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/certimeshConfig.cmake
                              INSTALL_DESTINATION ${CERTIMESH_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/certimeshConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/certimeshConfig.cmake
              ${PROJECT_BINARY_DIR}/certimeshConfigVersion.cmake
        DESTINATION ${CERTIMESH_INSTALL_CMAKEDIR})

# certimesh.pc. A static archive needs GMP on every link line, so for a static build the
# GMP libraries are named in Libs too (plain `pkg-config --libs certimesh` links);
# Requires.private keeps `pkg-config --static` and the include flags right either way.
get_target_property(_certimesh_predicates_type certimesh_predicates TYPE)
if(_certimesh_predicates_type STREQUAL "STATIC_LIBRARY")
  set(CERTIMESH_PC_LIBS_EXTRA " -lmpfr -lgmpxx -lgmp -lcrypto -lz")
else()
  set(CERTIMESH_PC_LIBS_EXTRA "")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(CERTIMESH_PC_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
else()
  set(CERTIMESH_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(CERTIMESH_PC_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}")
else()
  set(CERTIMESH_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
set(CERTIMESH_PC_PREFIX "@CERTIMESH_PC_PREFIX@")  # filled in at install time, below
configure_file(${PROJECT_SOURCE_DIR}/cmake/certimesh.pc.in ${PROJECT_BINARY_DIR}/certimesh.pc.in.configured
               @ONLY)
# The prefix is only known at install time (cmake --install --prefix may change it).
install(CODE "
  set(_certimesh_prefix \"\${CMAKE_INSTALL_PREFIX}\")
  file(READ \"${PROJECT_BINARY_DIR}/certimesh.pc.in.configured\" _certimesh_pc)
  string(REPLACE \"@CERTIMESH_PC_PREFIX@\" \"\${_certimesh_prefix}\" _certimesh_pc \"\${_certimesh_pc}\")
  file(WRITE \"${PROJECT_BINARY_DIR}/certimesh.pc\" \"\${_certimesh_pc}\")
")
install(FILES ${PROJECT_BINARY_DIR}/certimesh.pc DESTINATION ${CERTIMESH_INSTALL_PKGCONFIGDIR})
