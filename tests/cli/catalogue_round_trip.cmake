# cmake -P: the tableau file that `geomint-scheme --print-tableau --scheme NAME` prints is read
# back by `--analyse --tableau FILE` with the same CSV row as `--analyse --scheme NAME`.
#   SCHEME: the geomint-scheme executable; NAME: a catalogue method; FILE: where to write.
execute_process(COMMAND ${SCHEME} --print-tableau --scheme ${NAME} RESULT_VARIABLE status OUTPUT_FILE ${FILE}
                ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "--print-tableau --scheme ${NAME}: exit ${status}: ${err}")
endif()
execute_process(COMMAND ${SCHEME} --analyse --scheme ${NAME} --csv RESULT_VARIABLE s1 OUTPUT_VARIABLE by_name ERROR_VARIABLE e1)
execute_process(COMMAND ${SCHEME} --analyse --tableau ${FILE} --csv RESULT_VARIABLE s2 OUTPUT_VARIABLE by_file ERROR_VARIABLE e2)
if(NOT s1 EQUAL 0 OR NOT s2 EQUAL 0)
  message(FATAL_ERROR "--analyse: exit ${s1} (${e1}) and ${s2} (${e2})")
endif()
if(NOT by_name STREQUAL by_file OR NOT by_name MATCHES "\n${NAME},")
  message(FATAL_ERROR "--analyse --scheme ${NAME}:\n${by_name}\n--analyse --tableau ${FILE}:\n${by_file}")
endif()
