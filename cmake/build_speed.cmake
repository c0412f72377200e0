# Compiling less and less often (docs/building.md has the measurements behind each choice).
#
# ccache, where it is installed: every compile goes through it, with its cache outside the clone
# (ccache's own default, ~/.cache/ccache), so that a later build, in this clone or another, reuses
# what an earlier one compiled. The settings make hits independent of the clone's folder (paths
# below the clone are hashed relative to it; the working directory is not hashed into the debug
# information) and let precompiled headers be cached. DRAPE_CCACHE=OFF compiles directly.
option(DRAPE_CCACHE "Compile through ccache when it is installed" ON)
option(DRAPE_PRECOMPILED_HEADERS "Precompile the library headers most units include" OFF)
find_program(DRAPE_CCACHE_PROGRAM ccache)
if(DRAPE_CCACHE AND DRAPE_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER
      ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=1
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
      ${DRAPE_CCACHE_PROGRAM})
  message(STATUS "drape: compiling through ${DRAPE_CCACHE_PROGRAM}")
  if(DRAPE_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-fpch-preprocess)  # lets ccache hash a unit that uses a GCC PCH
  endif()
endif()

# Precompiled headers, off by default (DRAPE_PRECOMPILED_HEADERS=ON turns them on): the library
# headers that most units include, parsed once per target instead of once per unit. Measured on
# the 2-core machine (docs/building.md): a unit compiles about 1 s faster with them, but a cold
# Release build with them and ccache took 735 s against 609 s without either, and a GCC PCH, built
# anew in every clone, is part of the hash of every unit that uses it, so a clone in another
# folder missed the cache for all of them. Only headers of Debian's packages, never drape's own.
set(DRAPE_PRECOMPILED_HEADER_LIST
    <algorithm> <cmath> <filesystem> <fstream> <functional> <map> <memory> <sstream> <string>
    <vector> <Eigen/Core> <ceres/jet.h> <cholmod.h>)
function(drape_precompile_headers target)
  if(DRAPE_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${DRAPE_PRECOMPILED_HEADER_LIST} ${ARGN})
  endif()
endfunction()

# Unity builds, on by default (DRAPE_UNITY_BUILD=OFF compiles every unit by itself): the units of
# one folder are compiled in batches of DRAPE_UNITY_BATCH_SIZE, each batch one generated unit
# (build/unity/<target>/<folder>_<n>.cc) that includes them, so Eigen, Ceres, CHOLMOD, GoogleTest
# and the standard library are parsed once per batch instead of once per unit (docs/building.md
# has the measurement). CMake's own UNITY_BUILD names the units by absolute path, which makes every
# batch's text, and so its ccache hash, differ from one clone's folder to another's; these include
# them relative to the clone (`#include "src/scene/mesh.cc"`, found through the target's include
# path), so a second clone reuses the first one's objects. A unit with a compile definition or an
# include path of its own (version.cc, test_paths.cc), or generated in the build folder, is compiled
# by itself; units that share a COMPILE_OPTIONS (the fuzzer's coverage instrumentation of
# fuzz/CMakeLists.txt) are batched together and their batch gets it. Call it once a target's sources and their properties are final.
option(DRAPE_UNITY_BUILD "Compile each folder's units in batches (unity build)" ON)
set(DRAPE_UNITY_BATCH_SIZE 8 CACHE STRING "Units per batch of the unity build")
function(drape_unity_build target)
  if(NOT DRAPE_UNITY_BUILD)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  set(kept_alone)
  set(batch_keys)
  foreach(source ${sources})
    get_source_file_property(definitions ${source} COMPILE_DEFINITIONS)
    get_source_file_property(includes ${source} INCLUDE_DIRECTORIES)
    cmake_path(IS_PREFIX PROJECT_SOURCE_DIR ${source} NORMALIZE in_clone)
    cmake_path(IS_PREFIX PROJECT_BINARY_DIR ${source} NORMALIZE generated)
    if(definitions OR includes OR NOT in_clone OR generated OR NOT source MATCHES "\\.cc$")
      list(APPEND kept_alone ${source})
      continue()
    endif()
    get_source_file_property(options ${source} COMPILE_OPTIONS)
    if(NOT options)
      set(options "")
    endif()
    cmake_path(RELATIVE_PATH source BASE_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE relative)
    cmake_path(GET relative PARENT_PATH folder)
    string(MAKE_C_IDENTIFIER "${folder}" key)
    if(options)
      string(MAKE_C_IDENTIFIER "${key}${options}" key)  # e.g. src_scene_fsanitize_fuzzer_no_link
    endif()
    if(NOT key IN_LIST batch_keys)
      list(APPEND batch_keys ${key})
      set(members_${key})
      set(options_${key} "${options}")
    endif()
    list(APPEND members_${key} ${relative})
  endforeach()
  set(unity_sources)
  foreach(key ${batch_keys})
    set(batch 0)
    set(count 0)
    set(text "")
    list(LENGTH members_${key} remaining)
    foreach(relative ${members_${key}})
      string(APPEND text "#include \"${relative}\"\n")
      math(EXPR count "${count} + 1")
      math(EXPR remaining "${remaining} - 1")
      if(count EQUAL DRAPE_UNITY_BATCH_SIZE OR remaining EQUAL 0)
        set(unit ${PROJECT_BINARY_DIR}/unity/${target}/${key}_${batch}.cc)
        file(CONFIGURE OUTPUT ${unit} CONTENT "// Generated by drape_unity_build (cmake/build_speed.cmake).\n${text}")
        if(options_${key})
          set_source_files_properties(${unit} PROPERTIES COMPILE_OPTIONS "${options_${key}}")
        endif()
        list(APPEND unity_sources ${unit})
        math(EXPR batch "${batch} + 1")
        set(count 0)
        set(text "")
      endif()
    endforeach()
  endforeach()
  set_target_properties(${target} PROPERTIES SOURCES "${kept_alone};${unity_sources}")
endfunction()
