# The Python module (python/, docs/python.md): built when the Python headers and pybind11 are
# found (RADARPR_BUILD_PYTHON=AUTO, the default; ON requires them, OFF skips it).
set(RADARPR_BUILD_PYTHON AUTO CACHE STRING "Build the Python module: AUTO, ON or OFF")
set_property(CACHE RADARPR_BUILD_PYTHON PROPERTY STRINGS AUTO ON OFF)

set(radarpr_python_missing "")
if(NOT RADARPR_BUILD_PYTHON STREQUAL "OFF")
  # Debian installs pybind11, numpy and pytest for its own interpreter (python3-pybind11,
  # python3-numpy, python3-pytest); an interpreter earlier on PATH (pyenv, conda) usually lacks
  # them. -DPython3_EXECUTABLE=... picks another one.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
  if(NOT Python3_FOUND)
    set(radarpr_python_missing "the Python headers (python3-dev)")
  else()
    # Found after Python3, pybind11 builds for that interpreter (its FindPython mode).
    find_package(pybind11 2.10 CONFIG QUIET)
    if(NOT pybind11_FOUND)
      set(radarpr_python_missing "pybind11 (pybind11-dev or python3-pybind11)")
    endif()
  endif()
endif()

if(RADARPR_BUILD_PYTHON STREQUAL "OFF")
  set(RADARPR_BUILD_PYTHON OFF)
elseif(radarpr_python_missing)
  if(RADARPR_BUILD_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "RADARPR_BUILD_PYTHON=ON but ${radarpr_python_missing} was not found")
  endif()
  message(STATUS "Python module not built: ${radarpr_python_missing} not found (apt install "
                 "python3-dev python3-pybind11, or -DRADARPR_BUILD_PYTHON=OFF)")
  set(RADARPR_BUILD_PYTHON OFF)
else()
  message(STATUS "Python module: built for ${Python3_EXECUTABLE} (${Python3_VERSION})")
  set(RADARPR_BUILD_PYTHON ON)
  # Where `cmake --install` puts the module, relative to the prefix: the interpreter's own
  # layout for a prefix (lib/python3.X/site-packages), which PYTHONPATH then names.
  if(NOT DEFINED RADARPR_PYTHON_INSTALL_DIR)
    execute_process(
      COMMAND ${Python3_EXECUTABLE} -c
              "import sysconfig; print(sysconfig.get_path('platlib', 'posix_prefix', vars={'platbase': '.', 'base': '.'}))"
      OUTPUT_VARIABLE radarpr_python_platlib OUTPUT_STRIP_TRAILING_WHITESPACE)
    string(REGEX REPLACE "^\\./" "" radarpr_python_platlib "${radarpr_python_platlib}")
    set(RADARPR_PYTHON_INSTALL_DIR "${radarpr_python_platlib}" CACHE STRING
        "Where cmake --install puts the Python module, relative to the prefix")
  endif()
endif()
