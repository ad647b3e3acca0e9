# cmake -P: runs COMMAND (a ;-list), checks its exit status (EXPECT_EXIT zero|nonzero) and that
# stdout + stderr match EXPECT_REGEX.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(EXPECT_EXIT STREQUAL "zero" AND NOT status EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${status}:\n${all}")
elseif(EXPECT_EXIT STREQUAL "nonzero" AND status EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit, got 0:\n${all}")
endif()
if(NOT all MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}':\n${all}")
endif()
message(STATUS "exit ${status}, output matches '${EXPECT_REGEX}'")
