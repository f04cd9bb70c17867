# .ci/run with no conformance data beside the clone: it must fail, saying what is missing.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/shared)
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PX_SHARED_DIR=${WORK_DIR}/shared PX_BUILD_DIR=${WORK_DIR}/build
          PX_CMAKE_ARGS= ${SOURCE_DIR}/.ci/run
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(expected "PX_CONFORMANCE is ON but the conformance data is missing: ${WORK_DIR}/shared/testdata/graphics-snippets/example_1_conemap.png")
# CMake wraps its error messages: compare with the white space collapsed.
string(REGEX REPLACE "[ \n]+" " " said "${out}${err}")
string(FIND "${said}" "${expected}" at)
if(rc EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR ".ci/run without the conformance data: exit status ${rc}, expected a "
                      "failure saying \"${expected}\"; it said:\n${out}${err}")
endif()
if(EXISTS ${WORK_DIR}/build/build.ninja)
  message(FATAL_ERROR ".ci/run generated a build although the conformance data is missing")
endif()
message(STATUS ".ci/run refused: ${expected}")
file(REMOVE_RECURSE ${WORK_DIR})
