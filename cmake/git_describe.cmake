# Writes OUTPUT (a C++ header defining DRAPE_GIT_DESCRIBE) from `git describe --always --dirty` of
# SOURCE_DIR, run by the build at every build (CMakeLists.txt, drape_git_describe), so that the
# version in every result names the sources the binary was built from, not those CMake was last
# configured from. The file is rewritten only when the description changes, so that an unchanged
# tree rebuilds nothing. Outside a git clone (or without git) the description is empty.
set(describe "")
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT}" describe --always --dirty WORKING_DIRECTORY "${SOURCE_DIR}"
                  OUTPUT_VARIABLE describe OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
endif()
set(text "// Written by cmake/git_describe.cmake at build time.\n#define DRAPE_GIT_DESCRIBE \"${describe}\"\n")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
