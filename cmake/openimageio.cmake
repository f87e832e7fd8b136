# include(${PROJECT_SOURCE_DIR}/cmake/openimageio.cmake) finds OpenImageIO in the
# including directory's scope (imported targets are directory-scoped) and repairs a packaging
# bug of Debian 12: its OpenImageIO 2.4.7 target lists /usr/include/opencv4 among its
# include directories although OpenCV is an optional dependency that is usually not
# installed, and CMake refuses to generate targets that use an imported target with a
# missing include directory. Only the directories that exist are kept.
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
get_target_property(_shpack_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
set(_shpack_oiio_existing)
foreach(_shpack_dir IN LISTS _shpack_oiio_includes)
  if(EXISTS "${_shpack_dir}")
    list(APPEND _shpack_oiio_existing "${_shpack_dir}")
  endif()
endforeach()
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${_shpack_oiio_existing}")
unset(_shpack_oiio_includes)
unset(_shpack_oiio_existing)
