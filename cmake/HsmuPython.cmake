# The Python module `hsmu` (python/, docs/python.md), built when HSMU_BUILD_PYTHON is on and
# pybind11 and the Python headers are found (Debian: pybind11-dev python3-dev; the tests also
# need python3-numpy python3-pytest). The distribution's interpreter (/usr/bin/python3) is
# preferred to one earlier on PATH: it is the one the .deb installs into. Give
# -DPython_EXECUTABLE=... to build for another.
set(HSMU_PYTHON_MODULE OFF)
if(HSMU_BUILD_PYTHON AND HSMU_SANITIZE)
  # An instrumented module cannot be loaded into the uninstrumented interpreter.
  message(STATUS "Python module hsmu: not built in a sanitized build (HSMU_SANITIZE)")
elseif(HSMU_BUILD_PYTHON)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python 3.9 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_Development.Module_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(Python_Development.Module_FOUND AND pybind11_FOUND)
    set(HSMU_PYTHON_MODULE ON)
    message(STATUS "Python module hsmu: built for ${Python_EXECUTABLE} (pybind11 ${pybind11_VERSION})")
    add_subdirectory(python)
  elseif(NOT Python_Development.Module_FOUND)
    message(STATUS "Python module hsmu: not built: no Python headers for ${Python_EXECUTABLE} "
                   "(Debian: python3-dev; scripts/setup.sh installs it)")
  else()
    message(STATUS "Python module hsmu: not built: pybind11 not found "
                   "(Debian: pybind11-dev; scripts/setup.sh installs it)")
  endif()
endif()
