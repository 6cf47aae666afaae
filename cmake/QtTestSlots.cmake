# voxray_check_qtest_slots(SOURCE FUNCTIONS f... [NOT_RUN f...]): every test slot of the QtTest
# file SOURCE (the void f() under "private slots:") must be a ctest entry (FUNCTIONS) or named
# as not a check (NOT_RUN: a README figure). Any other fails the configure, so that no test is
# written and then never run.
function(voxray_check_qtest_slots source)
  cmake_parse_arguments(ARG "" "" "FUNCTIONS;NOT_RUN" ${ARGN})
  file(READ ${CMAKE_CURRENT_SOURCE_DIR}/${source} text)
  string(FIND "${text}" "private slots:" from)
  if(from EQUAL -1)
    message(FATAL_ERROR "${source}: no 'private slots:' section")
  endif()
  string(SUBSTRING "${text}" ${from} -1 text)
  string(REGEX REPLACE "\n (private|public|protected):.*" "" text "${text}")
  string(REGEX REPLACE "\n};.*" "" text "${text}")
  string(REGEX MATCHALL "\n  void [A-Za-z0-9_]+\\(\\)" slots "${text}")
  foreach(slot IN LISTS slots)
    string(REGEX REPLACE "\n  void ([A-Za-z0-9_]+).*" "\\1" slot "${slot}")
    if(NOT slot IN_LIST ARG_FUNCTIONS AND NOT slot IN_LIST ARG_NOT_RUN AND
       NOT slot MATCHES "^(init|cleanup|initTestCase|cleanupTestCase)$")
      message(FATAL_ERROR "${CMAKE_CURRENT_SOURCE_DIR}/${source}: the test ${slot} is not "
                          "registered: add it to the list of tests in "
                          "${CMAKE_CURRENT_LIST_FILE} (or NOT_RUN, for a figure)")
    endif()
  endforeach()
endfunction()
