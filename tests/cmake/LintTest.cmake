# .ci/lint fails on a file clang-format would change and on a clang-tidy finding, naming the
# check, and passes a clean file (PX_LINT_FILES narrows it to these files).
file(REMOVE_RECURSE ${WORK_DIR})
file(WRITE ${WORK_DIR}/good.cpp "int twice(int x) {\n    return 2 * x;\n}\n")
file(WRITE ${WORK_DIR}/bad_format.cpp "int  twice( int x ){return 2*x;}\n")
file(WRITE ${WORK_DIR}/bad_tidy.cpp "int* none() {\n    return 0;\n}\n")
set(commands "[")
foreach(name good bad_tidy)
  string(APPEND commands "{\"directory\": \"${WORK_DIR}\", \"command\": \"c++ -std=c++20 -c "
                         "${WORK_DIR}/${name}.cpp\", \"file\": \"${WORK_DIR}/${name}.cpp\"},")
endforeach()
string(REGEX REPLACE ",$" "]" commands "${commands}")
file(WRITE ${WORK_DIR}/build/compile_commands.json "${commands}\n")

function(lint file expect_rc pattern)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PX_BUILD_DIR=${WORK_DIR}/build
                          PX_LINT_FILES=${WORK_DIR}/${file} ${SOURCE_DIR}/.ci/lint all
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if((expect_rc EQUAL 0 AND NOT rc EQUAL 0) OR (NOT expect_rc EQUAL 0 AND rc EQUAL 0)
     OR NOT "${out}${err}" MATCHES "${pattern}")
    message(SEND_ERROR ".ci/lint on ${file}: exit status ${rc}, expected "
                       "${expect_rc} and output matching '${pattern}':\n${out}${err}")
  else()
    message(STATUS ".ci/lint on ${file}: exit status ${rc} as expected")
  endif()
endfunction()

lint(good.cpp 0 "clang-format: clean.*clang-tidy: 1 of 1 compiled files.*clang-tidy: clean")
lint(bad_format.cpp 1 "bad_format.cpp:1:4: error: code should be clang-formatted.*error: clang-format: the files above")
lint(bad_tidy.cpp 1 "bad_tidy.cpp:2:12: error: use nullptr \\[modernize-use-nullptr.*error: clang-tidy reported")
file(REMOVE_RECURSE ${WORK_DIR})
