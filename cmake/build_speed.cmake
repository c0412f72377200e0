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
