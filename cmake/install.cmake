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
# the installed tree. The licence (LICENSE, NOTICE) goes to share/doc/shpack; the Python module,
# when it is built, to SHPACK_PYTHON_INSTALL_DIR (python/CMakeLists.txt).
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

# The Python package shpack (SHPACK_BUILD_PYTHON: its extension _shpack, __init__.py and
# dask.py), where Debian's /usr/bin/python3 looks for packages that are not Debian's own
# (<prefix>/lib/python3/dist-packages/shpack; on PYTHONPATH for another prefix). The extension
# links lib/io and the core statically and the rest from the system, so it needs no RPATH.
# lib/io finds the OpenImageIO module first beside the shared object it is linked into
# (lib/io/src/oiio_plugin.h), so a relative symbolic link there names the one installed
# for the command: it holds for any --prefix and DESTDIR, and the module is not installed
# twice. The dist-info folder holds the metadata that importlib.metadata and pip read (name,
# version, licence); INSTALLER says that pip did not install it, and without a RECORD pip
# will not remove it.
if(TARGET shpack_python)
  set(SHPACK_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
      "Where `cmake --install` puts the Python module shpack, relative to the prefix (or absolute)")
  install(TARGETS shpack_python LIBRARY DESTINATION ${SHPACK_PYTHON_INSTALL_DIR}/shpack)
  install(FILES ${SHPACK_PYTHON_SOURCES} DESTINATION ${SHPACK_PYTHON_INSTALL_DIR}/shpack)
  install(CODE "
    set(py_dir \"${SHPACK_PYTHON_INSTALL_DIR}/shpack\")
    set(plugin_dir \"${SHPACK_PLUGIN_INSTALL_DIR}\")
    foreach(dir py_dir plugin_dir)
      if(NOT IS_ABSOLUTE \"\${\${dir}}\")
        set(\${dir} \"\${CMAKE_INSTALL_PREFIX}/\${\${dir}}\")
      endif()
    endforeach()
    file(RELATIVE_PATH target \"\${py_dir}\" \"\${plugin_dir}/$<TARGET_FILE_NAME:shpack_oiio>\")
    set(link \"\$ENV{DESTDIR}\${py_dir}/$<TARGET_FILE_NAME:shpack_oiio>\")
    message(STATUS \"Installing: \${link} -> \${target}\")
    file(CREATE_LINK \"\${target}\" \"\${link}\" SYMBOLIC)
  ")
  set(shpack_dist_info ${PROJECT_BINARY_DIR}/python/shpack-${PROJECT_VERSION}.dist-info)
  configure_file(${PROJECT_SOURCE_DIR}/python/METADATA.in ${shpack_dist_info}/METADATA @ONLY)
  file(WRITE ${shpack_dist_info}/INSTALLER "cmake\n")
  file(WRITE ${shpack_dist_info}/top_level.txt "shpack\n")
  install(FILES ${shpack_dist_info}/METADATA ${shpack_dist_info}/INSTALLER ${shpack_dist_info}/top_level.txt
                ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/NOTICE
    DESTINATION ${SHPACK_PYTHON_INSTALL_DIR}/shpack-${PROJECT_VERSION}.dist-info)
endif()

# The licence of everything above, where Debian keeps a package's (share/doc/<package>).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/NOTICE
  DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Everything the rules above install, as one target: `cmake --install` of a tree in which
# only some targets were built (CI builds only what it runs) fails on the first missing file,
# so a build that is to be installed builds this (python.installed_module needs it).
add_custom_target(shpack_installable)
add_dependencies(shpack_installable shpack_core shpack_c shpack shpack_oiio)
foreach(optional shpack_man shpack_python)
  if(TARGET ${optional})
    add_dependencies(shpack_installable ${optional})
  endif()
endforeach()
