# Runs one coinspect command and checks its exit code and output (ctest alone cannot check both).
#   cmake -DCOMMAND=<;-list> [-DSTDIN=<file>] -DEXPECT_RC=<n> -DEXPECT_REGEX=<regex> -P run_expect.cmake
if(DEFINED STDIN)
  execute_process(COMMAND ${COMMAND} INPUT_FILE ${STDIN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
else()
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
message("exit code ${rc}\n--- stdout\n${out}--- stderr\n${err}")
if(NOT rc STREQUAL EXPECT_RC)
  message(FATAL_ERROR "expected exit code ${EXPECT_RC}, got ${rc}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match: ${EXPECT_REGEX}")
endif()
