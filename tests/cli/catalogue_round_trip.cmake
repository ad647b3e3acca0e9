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
# With RUN (the geomint-run executable): the run of the method by name, `geomint-run --scheme
# NAME`, and of its tableau file, `--tableau FILE`, print the same rows (both convert the same
# exact coefficients to the scalar at its full precision).
if(DEFINED RUN)
  set(_args --system pendulum --tau 0.25 --steps 8 --digits 50 --csv)
  execute_process(COMMAND ${RUN} --scheme ${NAME} ${_args} RESULT_VARIABLE r1 OUTPUT_VARIABLE run_name ERROR_VARIABLE e1)
  execute_process(COMMAND ${RUN} --tableau ${FILE} ${_args} RESULT_VARIABLE r2 OUTPUT_VARIABLE run_file ERROR_VARIABLE e2)
  if(NOT r1 EQUAL 0 OR NOT r2 EQUAL 0)
    message(FATAL_ERROR "geomint-run: exit ${r1} (${e1}) and ${r2} (${e2})")
  endif()
  if(NOT run_name STREQUAL run_file OR NOT run_name MATCHES "\n8,2,")
    message(FATAL_ERROR "geomint-run --scheme ${NAME}:\n${run_name}\n--tableau ${FILE}:\n${run_file}")
  endif()
endif()
