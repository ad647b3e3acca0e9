# cmake -P: runs COMMAND (a ;-list, geomint-modified --order K --csv of a symmetric method of
# order P on all two-colour trees) into a file and checks its rows order,tree,sigma,b:
# - 2 x COUNT trees of order K (COUNT per root colour, OEIS A000151);
# - b = 0 on every tree of every even order up to K: the modified equation of a symmetric method
#   has an expansion in even powers of h (Hairer, Lubich & Wanner, Geometric Numerical
#   Integration, 2nd ed. 2006, section IX.2, Theorem 2.2), so f_j = 0 for even j;
# - b = 0 at orders 2..P and a nonzero b at order P + 1.
# Lines are filtered by file(STRINGS ... REGEX) (the output has half a million rows).
set(csv "${CMAKE_CURRENT_BINARY_DIR}/modified_symmetric_${K}.csv")
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_FILE "${csv}" ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "exit ${status}: ${err}")
endif()
file(STRINGS "${csv}" top REGEX "^${K},")
list(LENGTH top n)
math(EXPR expected "2 * ${COUNT}")
if(NOT n EQUAL expected)
  message(FATAL_ERROR "${n} trees of order ${K}, ${expected} expected")
endif()
foreach(order RANGE 2 ${K})
  math(EXPR odd "${order} % 2")
  if(odd EQUAL 0 OR NOT order GREATER P)
    file(STRINGS "${csv}" bad REGEX "^${order},.*,[^,]*[1-9][^,]*$")
    if(bad)
      list(GET bad 0 first)
      message(FATAL_ERROR "order ${order}: b != 0 in '${first}'")
    endif()
  endif()
endforeach()
math(EXPR next "${P} + 1")
file(STRINGS "${csv}" leading REGEX "^${next},.*,[^,]*[1-9][^,]*$")
if(NOT leading)
  message(FATAL_ERROR "every b of order ${next} is 0: the method's order would exceed ${P}")
endif()
file(REMOVE "${csv}")
message(STATUS "order ${K}: ${n} trees; b = 0 at every even order and at 2..${P}, nonzero at ${next}")
