# Test helpers. Each Qt Test class is one executable and one ctest, with labels and a timeout.
#
#   px_add_qtest(NAME <name> SOURCES <files...> [LIBS <targets...>] [LABELS <labels...>]
#                [TIMEOUT <seconds>] [GL])
# GL tests need a context (Xvfb or EGL); the others run on Qt's offscreen platform.
#
#   px_add_cli_test(NAME <name> COMMAND <args...> [EXPECT <regex>] [FAIL] [LABELS <labels...>])
# Runs parallax-cli with the arguments; EXPECT matches its output, FAIL expects a non-zero exit.

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

function(px_add_cli_test)
  cmake_parse_arguments(T "FAIL" "NAME;EXPECT;TIMEOUT" "COMMAND;LABELS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${PX_TIMEOUT_SCALE}")
  add_test(NAME cli.${T_NAME} COMMAND $<TARGET_FILE:parallax-cli> ${T_COMMAND}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set(_labels cli ${T_LABELS})
  set_tests_properties(cli.${T_NAME} PROPERTIES LABELS "${_labels}" TIMEOUT ${T_TIMEOUT})
  if(T_EXPECT)
    set_tests_properties(cli.${T_NAME} PROPERTIES PASS_REGULAR_EXPRESSION "${T_EXPECT}")
  endif()
  if(T_FAIL)
    set_tests_properties(cli.${T_NAME} PROPERTIES WILL_FAIL TRUE)
  endif()
endfunction()
