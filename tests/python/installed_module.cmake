# cmake -P installed_module.cmake, by the ctest test python.installed_module
# (tests/python/CMakeLists.txt): installs the build tree BUILD_DIR into WORK_DIR/prefix and
# runs installed_module_test.py with PYTHON, whose PYTHONPATH names only the installed
# module's folder (PYTHON_DIR, relative to the prefix or absolute), so that nothing of the
# build tree can stand in for a file the install forgot.
foreach(var BUILD_DIR WORK_DIR PYTHON PYTHON_DIR TEST_SCRIPT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "installed_module.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "python.installed_module: `${ARGN}` failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${out}${err}")
endfunction()

set(prefix ${WORK_DIR}/prefix)
if(IS_ABSOLUTE "${PYTHON_DIR}")
  set(module_dir ${PYTHON_DIR})
else()
  set(module_dir ${prefix}/${PYTHON_DIR})
endif()
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run(${CMAKE_COMMAND} -E env --unset=SHPACK_CLI --unset=SHPACK_SOURCE_DIR
    PYTHONPATH=${module_dir} SHPACK_PREFIX=${prefix} SHPACK_MODULE_DIR=${module_dir}
    ${PYTHON} -B ${TEST_SCRIPT} -v)
file(REMOVE_RECURSE ${WORK_DIR})
