# cli(ARGS...): runs parallax-cli (the script's -DCLI=...) with ARGS, failing the script if it
# fails. For the fixtures' scripts that make their input with the CLI itself.
function(cli)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "parallax-cli ${ARGN} failed")
  endif()
endfunction()
