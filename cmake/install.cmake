# `cmake --install build --prefix P` (docs/package.md): the public headers (include/tecido/, never
# the internal tree), the static libraries, the command line, the suites' data and the CMake
# package (P/lib/cmake/tecido: tecido-config.cmake, tecido-config-version.cmake, the export set
# with namespace tecido::). Only targets every preset builds are installed (no test, bench or fuzz
# target), so any preset configures with these rules; install needs the libraries and `tecido`
# built, not the tests (scripts/consumer_test.sh builds just those).
include(CMakePackageConfigHelpers)

set(TECIDO_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/tecido")
set(TECIDO_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/tecido/data")

install(FILES include/tecido/plugin.h include/tecido/geometry.h include/tecido/core.h include/tecido/referee.h
              include/tecido/simulation.h include/tecido/harness.h "${PROJECT_BINARY_DIR}/include/tecido/version.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/tecido")

# The public names; the detail_ targets are link dependencies of tecido::harness, no API.
set_target_properties(tecido_core PROPERTIES EXPORT_NAME core)
set_target_properties(tecido_referee PROPERTIES EXPORT_NAME referee)
set_target_properties(tecido_harness PROPERTIES EXPORT_NAME harness)
set_target_properties(tecido_reference PROPERTIES EXPORT_NAME detail_reference)
set_target_properties(tecido_bullet PROPERTIES EXPORT_NAME detail_bullet)
set_target_properties(tecido_comparisons PROPERTIES EXPORT_NAME detail_comparisons)
install(TARGETS tecido_core tecido_referee tecido_harness tecido_reference tecido_bullet tecido_comparisons
        EXPORT tecido-targets ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(TARGETS tecido RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(EXPORT tecido-targets NAMESPACE tecido:: DESTINATION "${TECIDO_INSTALL_CMAKEDIR}")

install(FILES data/tolerances.json DESTINATION "${TECIDO_INSTALL_DATADIR}")
install(DIRECTORY data/scenes data/seed_tables DESTINATION "${TECIDO_INSTALL_DATADIR}")

configure_package_config_file(cmake/tecido-config.cmake.in "${PROJECT_BINARY_DIR}/tecido-config.cmake"
                              INSTALL_DESTINATION "${TECIDO_INSTALL_CMAKEDIR}" PATH_VARS TECIDO_INSTALL_DATADIR)
# Same major version, this version or later (0.x: every minor is a new API, so SameMinorVersion).
write_basic_package_version_file("${PROJECT_BINARY_DIR}/tecido-config-version.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/tecido-config.cmake" "${PROJECT_BINARY_DIR}/tecido-config-version.cmake"
        DESTINATION "${TECIDO_INSTALL_CMAKEDIR}")

# Everything the install rules above need built, and nothing else (scripts/consumer_test.sh).
add_custom_target(tecido-package)
add_dependencies(tecido-package tecido_core tecido_referee tecido_harness tecido_reference tecido_bullet
                 tecido_comparisons tecido)
