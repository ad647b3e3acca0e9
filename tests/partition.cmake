# The partition check of one suites executable (tests/CMakeLists.txt, geomint_add_catch_test):
# every test case the executable holds is run by exactly one ctest entry. A test case that no
# filter selects (for instance one defined in a header, whose file tag no entry names) would
# otherwise never run, and one that two filters select would run twice.
# Usage: cmake -DEXECUTABLE=<path> "-DFILTERS=<filter>|<filter>|..." -P partition.cmake
function(list_names out)
  execute_process(COMMAND ${EXECUTABLE} --list-test-names-only ${ARGN}
                  OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(status LESS 0 OR NOT text)
    message(FATAL_ERROR "'${EXECUTABLE} --list-test-names-only ${ARGN}' failed (${status})")
  endif()
  string(REGEX REPLACE "\n+$" "" text "${text}")
  string(REPLACE "\n" ";" names "${text}")
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

list_names(all)
set(selected "")
string(REPLACE "|" ";" filters "${FILTERS}")
foreach(filter IN LISTS filters)
  list_names(names "-#" "${filter}")
  list(APPEND selected ${names})
endforeach()
list(SORT all)
list(SORT selected)
list(LENGTH all total)
list(LENGTH selected claimed)
if(NOT all STREQUAL selected)
  message(FATAL_ERROR "${EXECUTABLE}: ${total} test cases, but the ctest entries' filters select ${claimed} "
                      "(a test case in no entry, or in two):\nall: ${all}\nselected: ${selected}")
endif()
message(STATUS "${EXECUTABLE}: each of its ${total} test cases is in exactly one ctest entry")
