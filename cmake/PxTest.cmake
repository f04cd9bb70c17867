# Test helpers. Each Qt Test class is one executable and one ctest, with labels and a timeout.
#
#   px_add_qtest(NAME <name> SOURCES <files...> [LIBS <targets...>] [LABELS <labels...>]
#                [TIMEOUT <seconds>] [GL])
# GL tests need a context (Xvfb or EGL); the others run on Qt's offscreen platform.
#
#   px_add_cli_test(NAME <name> COMMAND <args...> [RC <status>] [EXPECT <regex...>]
#                   [REJECT <regex>] [CREATES <files...>] [UNCHANGED <file=twin...>]
#                   [OUT_FILE <file> OUT_EXPECT <regex>]
#                   [LABELS <labels...>] [ENV <VAR=value...>] [TIMEOUT <seconds>])
# Runs parallax-cli with the arguments and checks its exit status (RC, default 0) and its output
# (every EXPECT regex, stdout and stderr together): a failing command needs both, a succeeding one
# EXPECT or CREATES (see PxRunCli.cmake).

cmake_path(SET _px_default_shared NORMALIZE "${PROJECT_SOURCE_DIR}/../shared")
set(PX_SHARED_DIR "${_px_default_shared}" CACHE PATH
    "The folder holding testdata/ with the third-party conformance data (not redistributable)")
set(PX_CONFORMANCE AUTO CACHE STRING "The conformance test: AUTO (where its data is found), ON (required), OFF")
set_property(CACHE PX_CONFORMANCE PROPERTY STRINGS AUTO ON OFF)
include(PxConformance)
# Sanitized code runs several times slower; the timeouts guard against hangs, not speed.
if(PX_SANITIZE)
  set(PX_TIMEOUT_SCALE 8)
else()
  set(PX_TIMEOUT_SCALE 1)
endif()

function(px_add_qtest)
  cmake_parse_arguments(T "GL" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${PX_TIMEOUT_SCALE}")
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE Qt6::Test parallax-test-support ${T_LIBS})
  set_target_properties(${T_NAME} PROPERTIES AUTOMOC ON)
  add_test(NAME ${T_NAME} COMMAND ${T_NAME})
  set(_env "XDG_RUNTIME_DIR=${CMAKE_BINARY_DIR}/xdg-runtime")
  if(NOT T_GL)
    list(APPEND _env "QT_QPA_PLATFORM=offscreen")
  endif()
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
                       ENVIRONMENT "${_env}")
endfunction()

# Runs the test <name> (made by px_add_qtest) as <shards> ctest tests that ctest can run in
# parallel: <name> with PX_TEST_SHARD=0/<shards>, <name>.1 ... with 1/<shards> ..., each taking every
# <shards>-th of the test's cases (tests/support/TestSupport.h) under the test's labels and timeout.
#
#   px_shard_test(<name> <shards>)
function(px_shard_test name shards)
  get_test_property(${name} ENVIRONMENT _env)
  get_test_property(${name} LABELS _labels)
  get_test_property(${name} TIMEOUT _timeout)
  set_tests_properties(${name} PROPERTIES ENVIRONMENT "${_env};PX_TEST_SHARD=0/${shards}")
  math(EXPR _last "${shards} - 1")
  foreach(_i RANGE 1 ${_last})
    add_test(NAME ${name}.${_i} COMMAND ${name})
    set_tests_properties(${name}.${_i} PROPERTIES LABELS "${_labels}" TIMEOUT ${_timeout}
                         ENVIRONMENT "${_env};PX_TEST_SHARD=${_i}/${shards}")
  endforeach()
endfunction()

set(PX_RUN_CLI ${CMAKE_CURRENT_LIST_DIR}/PxRunCli.cmake)

function(px_add_cli_test)
  cmake_parse_arguments(T "FAIL" "NAME;RC;TIMEOUT;OUT_FILE;OUT_EXPECT"
                        "COMMAND;EXPECT;REJECT;CREATES;UNCHANGED;ONLY;LABELS;ENV" ${ARGN})
  if(T_FAIL)
    message(FATAL_ERROR "cli.${T_NAME}: FAIL checks no status or message: give RC and EXPECT")
  endif()
  if((T_OUT_FILE AND NOT T_OUT_EXPECT) OR (T_OUT_EXPECT AND NOT T_OUT_FILE))
    message(FATAL_ERROR "cli.${T_NAME}: OUT_FILE and OUT_EXPECT go together")
  endif()
  if(NOT DEFINED T_RC)
    set(T_RC 0)
  endif()
  if(NOT T_RC EQUAL 0 AND NOT T_EXPECT)
    message(FATAL_ERROR "cli.${T_NAME}: a failing command must be checked for its message (EXPECT)")
  endif()
  if(T_RC EQUAL 0 AND NOT T_EXPECT AND NOT T_CREATES)
    message(FATAL_ERROR "cli.${T_NAME}: check the output (EXPECT) or the files written (CREATES)")
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${PX_TIMEOUT_SCALE}")
  # Fault hooks (PX_TEST_*, PX_BAKE_TEST_INTERRUPT_AT) are read only by the test build of the
  # program (tests/faults/FaultCliMain.cpp); the shipped parallax-cli ignores them.
  set(_cli parallax-cli)
  if(T_ENV MATCHES "PX_(BAKE_)?TEST_")
    set(_cli parallax-cli-faults)
  endif()
  add_test(NAME cli.${T_NAME}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:${_cli}>;${T_COMMAND}"
                   -DEXPECT_RC=${T_RC} "-DEXPECT=${T_EXPECT}" "-DREJECT=${T_REJECT}"
                   "-DCREATES=${T_CREATES}" "-DUNCHANGED=${T_UNCHANGED}" "-DONLY=${T_ONLY}"
                   "-DOUT_FILE=${T_OUT_FILE}" "-DOUT_EXPECT=${T_OUT_EXPECT}" -P ${PX_RUN_CLI}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set(_labels cli ${T_LABELS})
  set_tests_properties(cli.${T_NAME} PROPERTIES LABELS "${_labels}" TIMEOUT ${T_TIMEOUT})
  # The user's cache folder is not the tests' (recommend keeps cone maps there).
  set_tests_properties(cli.${T_NAME} PROPERTIES ENVIRONMENT
                       "XDG_CACHE_HOME=${CMAKE_BINARY_DIR}/xdg-cache;${T_ENV}")
endfunction()
