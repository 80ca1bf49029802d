# Install rules of bezierpde: headers under <prefix>/include/bezierpde/, the libraries, `bpde`,
# and the CMake package (bezierpdeConfig.cmake, bezierpdeConfigVersion.cmake, bezierpdeTargets.cmake)
# under <prefix>/lib/cmake/bezierpde, so that an outside project writes
#
#   find_package(bezierpde 0.2 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE bezierpde::bezierpde)   # or bezierpde::core, ::io, ...
#
# Exported targets: bezierpde::core, ::solvers, ::cmc, ::io, ::view, ::step, ::checks, ::jobs and the umbrella
# bezierpde::bezierpde (README "Library use"; tests/package runs a consumer against an install).
include(CMakePackageConfigHelpers)

set(BPDE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/bezierpde CACHE STRING
    "Where bezierpdeConfig.cmake is installed (relative to the prefix)")

foreach(folder ${BPDE_HEADER_FOLDERS})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/bezierpde/${folder}
          COMPONENT development FILES_MATCHING PATTERN "*.h")
endforeach()
# The headers are installed as they are: they include each other as "bezierpde/<folder>/...", the
# only form that resolves in the build tree too (tests/package fails on any other).

install(TARGETS bpde_core bpde_solvers bpde_cmc bpde_io bpde_view bpde_step bpde_checks bpde_jobs bpde_lib
        EXPORT bezierpdeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS bpde RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# The STEP plugin (io/step_export.h) in <prefix>/<libdir>, where the library looks for it.
install(TARGETS bpde_step_plugin LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime)

install(EXPORT bezierpdeTargets NAMESPACE bezierpde:: DESTINATION ${BPDE_INSTALL_CMAKEDIR}
        COMPONENT development)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/bezierpdeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/bezierpdeConfig.cmake
                              INSTALL_DESTINATION ${BPDE_INSTALL_CMAKEDIR})
# 0.2 accepts 0.2.x only: the library has no stable API across minor versions yet.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/bezierpdeConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/bezierpdeConfig.cmake
              ${PROJECT_BINARY_DIR}/package/bezierpdeConfigVersion.cmake
        DESTINATION ${BPDE_INSTALL_CMAKEDIR} COMPONENT development)
