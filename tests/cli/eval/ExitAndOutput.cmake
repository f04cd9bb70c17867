# cmake -DCLI=parallax-cli -DARGS="a|b" -DRC=N -DEXPECT=regex [-DOUT=file -DOUT_EXPECT=regex]
#       -P ExitAndOutput.cmake
# Runs the command line and fails unless it exits with RC and its output (stdout and stderr) matches
# EXPECT; with OUT, the file it wrote must match OUT_EXPECT.
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND ${CLI} ${ARGS} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL RC)
  message(FATAL_ERROR "exit status ${_rc}, expected ${RC}\n${_out}${_err}")
endif()
if(NOT "${_out}${_err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match '${EXPECT}':\n${_out}${_err}")
endif()
if(OUT)
  file(READ "${OUT}" _file)
  if(NOT "${_file}" MATCHES "${OUT_EXPECT}")
    message(FATAL_ERROR "${OUT} does not match '${OUT_EXPECT}':\n${_file}")
  endif()
endif()
