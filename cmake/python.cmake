# Finds what the Python module needs (TECIDO_PYTHON: AUTO, ON, OFF) and sets TECIDO_PYTHON_ENABLED.
# Debian's pybind11 (2.10) with CMake's FindPython (PYBIND11_FINDPYTHON): the interpreter is
# /usr/bin/python3 unless Python_EXECUTABLE is given, because `python3` on PATH may be a version
# manager's shim without Debian's numpy (docs/python.md, "Build").
set(TECIDO_PYTHON_ENABLED OFF)
string(TOUPPER "${TECIDO_PYTHON}" tecido_python_mode)
if(NOT tecido_python_mode MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "TECIDO_PYTHON must be AUTO, ON or OFF, not \"${TECIDO_PYTHON}\"")
endif()
if(tecido_python_mode STREQUAL "OFF")
  return()
endif()
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python interpreter the module is built for")
endif()
set(PYBIND11_FINDPYTHON ON)
if(tecido_python_mode STREQUAL "ON")
  find_package(Python 3 REQUIRED COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.6 CONFIG REQUIRED)
else()
  find_package(Python 3 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(NOT Python_FOUND OR NOT pybind11_FOUND)
    message(STATUS "Python module: off (pybind11 or Python's development files not found; TECIDO_PYTHON=ON requires them)")
    return()
  endif()
endif()
# numpy is needed at run time only (pybind11 reaches its C API through Python), but a module
# that cannot be imported is no module: check it now.
execute_process(COMMAND "${Python_EXECUTABLE}" -c "import numpy" RESULT_VARIABLE tecido_numpy_status
                OUTPUT_QUIET ERROR_QUIET)
if(NOT tecido_numpy_status EQUAL 0)
  if(tecido_python_mode STREQUAL "ON")
    message(FATAL_ERROR "Python module: ${Python_EXECUTABLE} cannot import numpy (Debian: apt install python3-numpy)")
  endif()
  message(STATUS "Python module: off (${Python_EXECUTABLE} cannot import numpy)")
  return()
endif()
set(TECIDO_PYTHON_ENABLED ON)
# The static libraries go into a shared module.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
message(STATUS "Python module: on, for ${Python_EXECUTABLE} (${Python_VERSION}), pybind11 ${pybind11_VERSION}")
