# Writes drape's bash completion script: cmake -DDRAPE=<drape> -DOUTPUT=<file> -P this file.
get_filename_component(folder ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${folder})
execute_process(COMMAND ${DRAPE} completion bash OUTPUT_FILE ${OUTPUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(REMOVE ${OUTPUT})
  message(FATAL_ERROR "drape completion bash failed: ${status}")
endif()
