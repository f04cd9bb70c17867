# px_check_layer passes a clean folder and fails one whose file includes a forbidden folder's
# header, naming the file and the line.
include(${PX_MODULES}/PxLayering.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(WRITE ${WORK_DIR}/clean/Doc.h "#include \"model/Other.h\"\n#include <QString>\n")
file(WRITE ${WORK_DIR}/bad/Doc.cpp "#include \"model/Doc.h\"\n  # include \"panels/MapsPanel.h\"\n")
file(WRITE ${WORK_DIR}/check.cmake
     "include(${PX_MODULES}/PxLayering.cmake)\n"
     "px_check_layer(DIR \${DIR} LAYER model FORBIDDEN preview panels widgets jobs window)\n")
foreach(case clean bad)
  execute_process(COMMAND ${CMAKE_COMMAND} -DDIR=${WORK_DIR}/${case} -P ${WORK_DIR}/check.cmake
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(case STREQUAL "clean" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "a clean folder was refused: ${err}")
  endif()
  if(case STREQUAL "bad")
    if(rc EQUAL 0)
      message(FATAL_ERROR "a model file including panels/MapsPanel.h was accepted")
    endif()
    if(NOT err MATCHES "bad/Doc.cpp: # include \"panels/MapsPanel.h\"")
      message(FATAL_ERROR "the refusal does not name the file and the line: ${err}")
    endif()
  endif()
endforeach()
message(STATUS "layering check: clean folder passed, forbidden include refused")
