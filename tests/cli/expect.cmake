# cmake -P: runs COMMAND (a ;-list), checks its exit status and that stdout + stderr match
# EXPECT_REGEX.
#   EXPECT_EXIT: zero | nonzero (any exit status but 0, never a signal) | any (any exit status,
#                never a signal) | a number (exactly it)
#   STDOUT_FILE: optional; stdout goes there instead (e.g. /dev/full to test write failures)
#   EXPECT_EMPTY_STDERR: optional; stderr must be empty
# A command killed by a signal (crash, abort, sanitizer report with abort) fails every variant:
# CMake then reports a text such as "Child aborted" instead of a number.
if(STDOUT_FILE)
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_FILE ${STDOUT_FILE} ERROR_VARIABLE err)
  set(out "")
else()
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
set(all "${out}${err}")
if(NOT status MATCHES "^[0-9]+$")
  message(FATAL_ERROR "killed by a signal or not run: '${status}':\n${all}")
endif()
if(EXPECT_EXIT STREQUAL "zero" AND NOT status EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${status}:\n${all}")
elseif(EXPECT_EXIT STREQUAL "nonzero" AND status EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit, got 0:\n${all}")
elseif(EXPECT_EXIT MATCHES "^[0-9]+$" AND NOT status EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "expected exit ${EXPECT_EXIT}, got ${status}:\n${all}")
endif()
if(EXPECT_EMPTY_STDERR AND NOT err STREQUAL "")
  message(FATAL_ERROR "expected an empty stderr, got:\n${err}")
endif()
if(NOT all MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}':\n${all}")
endif()
message(STATUS "exit ${status}, output matches '${EXPECT_REGEX}'")
