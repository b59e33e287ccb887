# Runs COMMAND and passes when it exits with 2 and prints exactly one line, printable ASCII,
# matching EXPECT.
# A run that cannot make a GL context at all (77) is passed on as skipped.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
string(STRIP "${all}" all)
message("exit ${rc}: ${all}")
if(rc EQUAL 77)
  message("no GL context: skipped")  # matched by the test's SKIP_REGULAR_EXPRESSION
  return()
endif()
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit code 2, got ${rc}")
endif()
string(FIND "${all}" "\n" newline)
if(NOT newline EQUAL -1)
  message(FATAL_ERROR "expected one line of output")
endif()
if(all MATCHES "[^ -~]")
  message(FATAL_ERROR "expected printable ASCII only")
endif()
if(NOT all MATCHES "${EXPECT}")
  message(FATAL_ERROR "expected the line to match '${EXPECT}'")
endif()
