# include(cmake/install.cmake) from the top-level CMakeLists.txt: `cmake --install` rules.
#
# Installed: the core (shpack::core, a static library, the C++ API of lib/include/shpack/*.h),
# the C ABI (shpack::c, a shared library, shpack/shpack_c.h), the headers, and a CMake package,
# so that an importer writes
#   find_package(shpack 0.1 REQUIRED)
#   target_link_libraries(importer PRIVATE shpack::core)   # or shpack::c
# Also the shpack command (bin/shpack), its OpenImageIO module (lib/shpack/libshpack_oiio.so,
# opened on first use; lib/io/CMakeLists.txt), its man page (share/man/man1/shpack.1, made by
# help2man from `shpack --help`) and the bundled maps it measures when `shpack bench` is
# given no inputs (share/shpack/hdri: data/hdri's EXRs, README and licence; the command finds
# them from its own path, bin/../share/shpack/hdri). lib/io is not installed as a library: it
# needs OpenEXR and OpenSSL and serves the command. tests/install_consumer builds a project against
# the installed tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SHPACK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/shpack)

# shpack_options carries no compile options to importers (the core links it PRIVATE, so the
# export names it as link-only): only the sanitizer's link flags of a -DSHPACK_SANITIZE=ON
# build, which a static core built that way needs.
set_target_properties(shpack_options PROPERTIES EXPORT_NAME options)
install(TARGETS shpack_core shpack_c shpack_options EXPORT shpackTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/shpack DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT shpackTargets NAMESPACE shpack:: DESTINATION ${SHPACK_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shpackConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shpackConfig.cmake INSTALL_DESTINATION ${SHPACK_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shpackConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shpackConfig.cmake ${PROJECT_BINARY_DIR}/shpackConfigVersion.cmake
  DESTINATION ${SHPACK_INSTALL_CMAKEDIR})

# The command, its module and its data.
install(TARGETS shpack RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS shpack_oiio LIBRARY DESTINATION ${SHPACK_PLUGIN_INSTALL_DIR})
find_program(SHPACK_HELP2MAN help2man)
if(SHPACK_HELP2MAN)
  add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/shpack.1
    COMMAND ${SHPACK_HELP2MAN} --no-info --name "HDR environment maps to Unity L2 spherical harmonics"
            --output ${PROJECT_BINARY_DIR}/shpack.1 $<TARGET_FILE:shpack>
    DEPENDS shpack
    COMMENT "Generating the man page shpack.1 from shpack --help")
  add_custom_target(shpack_man ALL DEPENDS ${PROJECT_BINARY_DIR}/shpack.1)
  install(FILES ${PROJECT_BINARY_DIR}/shpack.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found (scripts/install-deps.sh installs it): no man page is installed")
endif()
file(GLOB shpack_bundled_maps ${PROJECT_SOURCE_DIR}/data/hdri/*.exr)
install(FILES ${shpack_bundled_maps} ${PROJECT_SOURCE_DIR}/data/hdri/README.md
              ${PROJECT_SOURCE_DIR}/data/hdri/license.txt
  DESTINATION ${CMAKE_INSTALL_DATADIR}/shpack/hdri)
