# drape's Python module (python/): the package `drape` (python/drape/__init__.py) around the
# extension `_drape` (python/drape_module.cc, pybind11) over drape_core, built into
# build/python/drape (PYTHONPATH=build/python), installed where Debian's Python looks for that
# prefix, and tested by pytest (python/tests) as the CTest test PythonModule.
#   Debian: pybind11-dev python3-dev (build), python3-numpy (use), python3-pytest (tests).
# setup.py (`pip install .`) builds the target _drape with DRAPE_PYTHON_REQUIRED=ON: without
# pybind11 or the headers the configure fails, instead of the build not finding the target.
# Debian's Python, the one README's test command installs NumPy, pytest, matplotlib and SciPy
# for, unless a Python is chosen (-DPython3_EXECUTABLE=): a python3 found earlier in PATH (pyenv's,
# a virtual environment's) has none of them.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module)
find_package(pybind11 CONFIG QUIET)
if(NOT Python3_FOUND OR NOT pybind11_FOUND)
  if(DRAPE_PYTHON_REQUIRED)
    message(FATAL_ERROR "pybind11 or the Python headers not found (Debian: pybind11-dev "
                        "python3-dev) for ${Python3_EXECUTABLE}: the Python module cannot be built")
  endif()
  message(STATUS "pybind11 or the Python headers not found (Debian: pybind11-dev python3-dev): "
                 "no Python module")
  return()
endif()
set(DRAPE_PYTHON_FOUND ON)
set(DRAPE_PYTHON_PACKAGE ${PROJECT_BINARY_DIR}/python/drape)
# NO_EXTRAS: no link-time optimisation (a serial LTO link of the module over drape_core costs CI
# time and gains nothing measurable: the solver runs in drape_core, compiled without LTO).
pybind11_add_module(_drape MODULE NO_EXTRAS ${PROJECT_SOURCE_DIR}/python/drape_module.cc)
target_link_libraries(_drape PRIVATE drape_core)
set_target_properties(_drape PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${DRAPE_PYTHON_PACKAGE})
# The package's pure-Python files beside the module: its modules (*.py), the type stubs (*.pyi)
# and PEP 561's marker py.typed; CMake configures again when one is added or removed.
file(GLOB DRAPE_PYTHON_FILES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/drape/*.py
     ${PROJECT_SOURCE_DIR}/python/drape/*.pyi ${PROJECT_SOURCE_DIR}/python/drape/py.typed)
add_custom_command(TARGET _drape POST_BUILD
                   COMMAND ${CMAKE_COMMAND} -E copy_if_different
                           ${DRAPE_PYTHON_FILES} ${DRAPE_PYTHON_PACKAGE}/
                   VERBATIM)
add_custom_target(drape_python_package ALL
                  COMMAND ${CMAKE_COMMAND} -E copy_if_different
                          ${DRAPE_PYTHON_FILES} ${DRAPE_PYTHON_PACKAGE}/
                  DEPENDS _drape VERBATIM)

# Where Debian's Python finds a package under the install prefix: /usr/lib/python3/dist-packages
# (the .deb's prefix), else <prefix>/lib/python3.X/dist-packages (/usr/local's, and any other).
install(CODE "
  if(CMAKE_INSTALL_PREFIX STREQUAL \"/usr\")
    set(drape_python_dir \"\${CMAKE_INSTALL_PREFIX}/lib/python3/dist-packages\")
  else()
    set(drape_python_dir
        \"\${CMAKE_INSTALL_PREFIX}/lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages\")
  endif()
  file(INSTALL \"${DRAPE_PYTHON_PACKAGE}\" DESTINATION \"\${drape_python_dir}\"
       FILES_MATCHING PATTERN \"*.py\" PATTERN \"*.pyi\" PATTERN \"py.typed\"
       PATTERN \"_drape*.so\" PATTERN \"__pycache__\" EXCLUDE)
")
