# Runs cmake/check_module_includes.cmake on a fixture tree and checks its
# verdict, so the checker is shown to fail where it must (a ctest test):
#   cmake -DFIXTURE=<dir> -DEXPECT=pass|fail [-DMESSAGE=<regex>] -P expect_check.cmake
# FIXTURE holds manifest.cmake and src/stochtex/; MESSAGE must match the
# checker's output when given.
cmake_minimum_required(VERSION 3.25)
execute_process(
  COMMAND ${CMAKE_COMMAND} -DMANIFEST=${FIXTURE}/manifest.cmake -DROOT=${FIXTURE}/src/stochtex
          -P ${CMAKE_CURRENT_LIST_DIR}/../../cmake/check_module_includes.cmake
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE out)
message("${out}")
if(EXPECT STREQUAL "pass" AND NOT rc EQUAL 0)
  message(FATAL_ERROR "the checker rejected ${FIXTURE} (exit ${rc}), which follows the order")
elseif(EXPECT STREQUAL "fail" AND rc EQUAL 0)
  message(FATAL_ERROR "the checker accepted ${FIXTURE}, which breaks the order")
endif()
if(DEFINED MESSAGE AND NOT out MATCHES "${MESSAGE}")
  message(FATAL_ERROR "the checker's output does not match \"${MESSAGE}\"")
endif()
