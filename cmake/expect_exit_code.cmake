# cmake -DCOMMAND=<program> [-DARGUMENTS=<a;b>] -DEXPECTED_EXIT_CODE=<n> [-DEXPECTED_STDERR=<text>] -P expect_exit_code.cmake
# Runs a program and fails unless it exits with the expected code and its standard error contains the expected text.
execute_process(COMMAND ${COMMAND} ${ARGUMENTS} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err
                INPUT_FILE /dev/null TIMEOUT 60)
message("exit code ${exit_code}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT exit_code STREQUAL EXPECTED_EXIT_CODE)
  message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT_CODE}, got ${exit_code}")
endif()
if(DEFINED EXPECTED_STDERR)
  string(FIND "${err}" "${EXPECTED_STDERR}" position)
  if(position EQUAL -1)
    message(FATAL_ERROR "standard error does not contain '${EXPECTED_STDERR}'")
  endif()
endif()
