# cmake -P script: installs geomint into a prefix, builds the outside project of
# docs/guide/your_own_tools.md (tools_project: hh-tools over the README's Henon-Heiles system,
# with geomint_add_tools) and runs its commands. The build is kept small for CI: --digits 16 and
# 50 only, no m = 9..16 (GEOMINT_TOOLS_DIGITS, GEOMINT_TOOLS_HIGH_M), at -O0: Clang 14 compiled
# it in 91 s of CPU time at -O0 against about 170 s at -O1, and its commands then run in 11 s.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${out}${err}")
  endif()
endfunction()
# expect(<regex> <command>...): runs the command, which must exit with 0 and print a match.
function(expect regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${ARGN}")
  message("$ ${shown}\n${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "exit status ${status}")
  endif()
  if(NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "output does not match '${regex}'")
  endif()
endfunction()
file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})
run(${CMAKE_COMMAND} --install ${GEOMINT_BUILD_DIR} --prefix ${PREFIX})
# (Not through run(): its ${ARGN} would split the list 16;50 into two arguments.)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX}
                        -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O0 -DNDEBUG"
                        "-DGEOMINT_TOOLS_DIGITS=16;50" -DGEOMINT_TOOLS_HIGH_M=OFF
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring the outside project failed (${status}):\n${out}${err}")
endif()
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD} --parallel 2)
set(tool ${CONSUMER_BUILD}/hh-tools)
# Expected values from exact mathematics and the schemes' published orders: the energy of the
# initial data is exactly 1/8 (q0 = 0, qdot0 = (3/10, 2/5)); the schemes conserve it up to their
# error at these steps. LPF on Gauss-interior nodes of degree m has order 2(m - 1) (Kong & Yang,
# J. Dyn. Control 2020), the Galerkin VI of degree m order 2m; both are symplectic for a natural
# Lagrangian, so their defect in double is at round-off (1e-1x).
expect("system henon-heiles, scheme lpf.m=2, equispaced.*energy = 0[.]12(49|50)"
       ${tool} run --system henon-heiles --steps 100)
expect("system henon-heiles, scheme gauss-2 .rkn, 2 stages.*energy = 0[.]12(4999|5000)"
       ${tool} run --system henon-heiles --tableau ${TABLEAU} --steps 100)
expect("system henon-heiles, scheme galerkin.m=4.*digits 50.*energy = 0[.]12(49999999999|50000000000)"
       ${tool} run --system henon-heiles --scheme galerkin --m 4 --digits 50 --steps 100)
expect("henon-heiles,lpf,gauss-interior,3,[0-9.]+,(3[.]9[0-9]|4[.]0[0-9]),[^,]+,ok"
       ${tool} order --system henon-heiles --scheme lpf --nodes gauss-interior --m 3 --steps 4,8,16,32,64 --csv)
expect("henon-heiles,lpf,gauss-interior,3,0[.]25,[0-9.]+e-1[0-9],ok"
       ${tool} symplectic --digits 16 --system henon-heiles --scheme lpf --nodes gauss-interior --m 3 --csv)
# modified: the energy error of the Galerkin VI m = 2 (order 4, symplectic) predicted from its
# modified equation (backward error analysis: H(y_n) - H(y_0) = -h^4 (H_5(y_n) - H_5(y_0)) +
# O(h^6)) against the measured one, two independent routes; within 2% at tau = 1/20.
execute_process(COMMAND ${tool} modified --scheme galerkin --m 2 --system henon-heiles --tau 0.1,0.05 --steps 400 --csv
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "\n0[.]05,400,([0-9])[.]([0-9][0-9][0-9])[0-9]*e-0*([0-9]+),([0-9])[.]([0-9][0-9][0-9])[0-9]*e-0*([0-9]+)")
  message(FATAL_ERROR "hh-tools modified: status ${status}\n${out}${err}")
endif()
# The two values as integers of four digits at the same exponent.
set(predicted "${CMAKE_MATCH_1}${CMAKE_MATCH_2}")
set(measured "${CMAKE_MATCH_4}${CMAKE_MATCH_5}")
math(EXPR shift "${CMAKE_MATCH_6} - ${CMAKE_MATCH_3}")
if(shift EQUAL 1)
  math(EXPR measured "${measured} / 10")
elseif(shift EQUAL -1)
  math(EXPR predicted "${predicted} / 10")
elseif(NOT shift EQUAL 0)
  message(FATAL_ERROR "hh-tools modified: predicted and measured differ by a factor 10^${shift}:\n${out}")
endif()
math(EXPR deviation "100 * (${predicted} - ${measured})")
if(deviation LESS 0)
  math(EXPR deviation "-${deviation}")
endif()
math(EXPR allowed "2 * ${measured}")
if(deviation GREATER allowed)
  message(FATAL_ERROR "hh-tools modified: prediction and measurement differ by more than 2%:\n${out}")
endif()
message("consumer tools: ok")
