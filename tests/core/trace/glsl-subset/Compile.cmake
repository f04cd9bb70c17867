# Compiles Snippet.cpp with one SNIPPET: 0 must compile cleanly; any other must fail with an
# error naming EXPECT (the check that caught it).
execute_process(COMMAND ${COMPILER} -std=c++20 -fsyntax-only -DSNIPPET=${SNIPPET} -I${INCLUDE}
                        ${CMAKE_CURRENT_LIST_DIR}/Snippet.cpp
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(SNIPPET EQUAL 0)
  if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
    message(FATAL_ERROR "the clean snippet did not compile cleanly (${rc}):\n${out}${err}")
  endif()
elseif(rc EQUAL 0 OR NOT err MATCHES "error: [^\n]*\\[-Werror=${EXPECT}\\]")
  message(FATAL_ERROR "snippet ${SNIPPET}: expected an error [-Werror=${EXPECT}], got (${rc}):\n"
                      "${out}${err}")
endif()
