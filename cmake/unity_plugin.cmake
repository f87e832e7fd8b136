# unity_plugin.cmake - stages the built C ABI library (shpack_c) into the Unity package, as
# unity/Plugins/<platform>/<file> with the name, folder and import settings (the committed
# .meta beside it) that Unity's plugin importer expects (docs/unity.md):
#
#   Linux x86-64   unity/Plugins/Linux/x86_64/libshpack_c.so
#   Windows x64    unity/Plugins/Windows/x86_64/shpack_c.dll
#   macOS          unity/Plugins/macOS/libshpack_c.dylib   (universal with the macos preset)
#
# The binaries are ignored by git (unity/Plugins/.gitignore). A sanitised build is not staged:
# its library needs the sanitizer runtimes, which a Unity Editor does not load.
option(SHPACK_STAGE_UNITY_PLUGIN "Copy shpack_c into unity/Plugins/<platform>/ after each build" ON)

set(shpack_unity_plugins ${PROJECT_SOURCE_DIR}/unity/Plugins)
if(CMAKE_SYSTEM_NAME STREQUAL "Linux" AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(shpack_unity_plugin ${shpack_unity_plugins}/Linux/x86_64/libshpack_c.so)
elseif(CMAKE_SYSTEM_NAME STREQUAL "Windows" AND CMAKE_SIZEOF_VOID_P EQUAL 8)
  set(shpack_unity_plugin ${shpack_unity_plugins}/Windows/x86_64/shpack_c.dll)
elseif(CMAKE_SYSTEM_NAME STREQUAL "Darwin")
  set(shpack_unity_plugin ${shpack_unity_plugins}/macOS/libshpack_c.dylib)
else()
  set(shpack_unity_plugin)
endif()

if(SHPACK_STAGE_UNITY_PLUGIN AND SHPACK_SANITIZE)
  message(STATUS "shpack: the sanitised shpack_c is not staged into unity/Plugins")
elseif(SHPACK_STAGE_UNITY_PLUGIN AND NOT shpack_unity_plugin)
  message(STATUS "shpack: no Unity plugin folder for ${CMAKE_SYSTEM_NAME} ${CMAKE_SYSTEM_PROCESSOR}; not staged")
elseif(SHPACK_STAGE_UNITY_PLUGIN)
  # copy_if_different: a rebuild that changes nothing leaves the staged file (and Unity's
  # import of it) alone.
  add_custom_command(TARGET shpack_c POST_BUILD
    COMMAND ${CMAKE_COMMAND} -E copy_if_different $<TARGET_FILE:shpack_c> ${shpack_unity_plugin}
    COMMENT "Staging shpack_c into ${shpack_unity_plugin}"
    VERBATIM)
endif()
