# include(cmake/install.cmake) from the top-level CMakeLists.txt: `cmake --install` rules.
#
# Installed: the core (shpack::core, a static library, the C++ API of lib/include/shpack/*.h),
# the C ABI (shpack::c, a shared library, shpack/shpack_c.h), the headers, and a CMake package,
# so that an importer writes
#   find_package(shpack 0.1 REQUIRED)
#   target_link_libraries(importer PRIVATE shpack::core)   # or shpack::c
# lib/io and the shpack command are not installed: they need OpenImageIO and are tools of this
# repository. tests/install_consumer builds a project against the installed tree.
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
