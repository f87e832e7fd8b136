# include(cmake/python.cmake): what the Python module (python/, SHPACK_BUILD_PYTHON) is built
# against. Debian's pybind11-dev (header-only) and the interpreter whose packages Debian
# installs, /usr/bin/python3, with python3-dev and python3-numpy: the `python3` found first on
# PATH on these machines may be another interpreter, which does not see Debian's NumPy and
# whose headers may not be installed. SHPACK_PYTHON names another interpreter.
set(SHPACK_PYTHON /usr/bin/python3 CACHE FILEPATH "The Python interpreter the module is built for and tested with")
set(Python3_EXECUTABLE ${SHPACK_PYTHON})
set(PYTHON_EXECUTABLE ${SHPACK_PYTHON})  # pybind11's older variable, for its own checks
# Python3 before pybind11: pybind11 then uses this interpreter (its FindPython mode).
find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter Development.Module)
find_package(pybind11 2.6 CONFIG REQUIRED)
