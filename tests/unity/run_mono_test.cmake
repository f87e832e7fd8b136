# cmake -P run_mono_test.cmake, by the ctest test unity_package_mono (tests/CMakeLists.txt):
# compiles the Unity package (unity/Runtime, unity/Editor) with Mono's C# compiler against
# the UnityEngine/UnityEditor stubs of this folder and Json.NET, together with the tests
# (ShpackMonoTest*.cs) and the C# that `shpack convert --format csharp` writes for
# data/hdri/studio.exr, then runs it under Mono with libshpack_c from the build (LIB_DIR).
# PRELOAD: the sanitizer runtimes of a -DSHPACK_SANITIZE=ON build, whose libshpack_c needs
# them loaded first in the (unsanitised) Mono process; leak detection is off there, as Mono
# does not free its heap at exit.
foreach(var CLI LIB_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_mono_test.cmake: -D${var}=... is required")
  endif()
endforeach()
find_program(MCS mcs)
find_program(MONO mono)
# Json.NET, which Unity's com.unity.nuget.newtonsoft-json package provides (Debian's build of
# an older release, with the same API the package uses).
file(GLOB newtonsoft /usr/lib/cli/Newtonsoft.Json-*/Newtonsoft.Json.dll)
if(NOT MCS OR NOT MONO OR NOT newtonsoft)
  message("unity_package_mono: mcs, mono or Newtonsoft.Json.dll not found; scripts/install-deps.sh installs "
          "mono-mcs, mono-runtime and libnewtonsoft-json-cil-dev")
  cmake_language(EXIT 77)  # ctest: skipped
endif()
list(GET newtonsoft 0 newtonsoft)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "unity_package_mono: `${ARGN}` failed (${rc})")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(studio ${SOURCE_DIR}/data/hdri/studio.exr)
run(${CLI} convert ${studio} -o ${WORK_DIR}/studio.json)
run(${CLI} convert ${studio} --format csharp -o ${WORK_DIR}/ShpackStudio.cs)

file(GLOB package_sources ${SOURCE_DIR}/unity/Runtime/*.cs ${SOURCE_DIR}/unity/Editor/*.cs)
set(test_dir ${SOURCE_DIR}/tests/unity)
file(GLOB stubs ${test_dir}/UnityEngine*.cs ${test_dir}/UnityEditor*.cs)
file(GLOB tests ${test_dir}/ShpackMonoTest*.cs)
file(COPY ${newtonsoft} DESTINATION ${WORK_DIR})  # beside the test, where Mono looks first
run(${MCS} -nologo -warnaserror -langversion:7 -out:${WORK_DIR}/ShpackMonoTest.exe -r:System.dll -r:System.Core.dll
    -r:${WORK_DIR}/Newtonsoft.Json.dll ${stubs} ${package_sources} ${tests} ${WORK_DIR}/ShpackStudio.cs)

set(environment LD_LIBRARY_PATH=${LIB_DIR})
if(PRELOAD)
  string(REPLACE ";" " " preload "${PRELOAD}")
  list(APPEND environment "LD_PRELOAD=${preload}" ASAN_OPTIONS=detect_leaks=0)
endif()
run(${CMAKE_COMMAND} -E env ${environment} ${MONO} --debug ${WORK_DIR}/ShpackMonoTest.exe ${CLI} ${WORK_DIR}
    ${WORK_DIR}/studio.json)
file(REMOVE_RECURSE ${WORK_DIR})
