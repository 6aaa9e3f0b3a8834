# ctest tests for the instrumented build: one per GoogleTest suite instead of one per
# test. Each process of the sanitized suite pays 0.3–0.5 s before its first test
# (ASan's shadow memory and the loader: 12 000 page faults, mostly kernel time on this
# VM, `perf stat`); 756 tests are 113 suites. Each suite's tests run in one process,
# write their own times to a GoogleTest XML file (cmake/TestBudget.cmake reads them), and
# the suites with more tests run first (COST), so that the last to finish is short.
#   cmake -DTEST_EXECUTABLE=... -DEXCLUDE=a.b:c.d -DLABEL=unit -DXML_DIR=... -DOUT=file -P GtestSuites.cmake
cmake_minimum_required(VERSION 3.20)
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "GtestSuites: ${TEST_EXECUTABLE} --gtest_list_tests failed (${status})")
endif()
string(REPLACE ":" ";" excluded "${EXCLUDE}")
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.")  # a suite's line; its tests follow, indented
    set(suite "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^  ([A-Za-z0-9_/]+)")
    set(name "${suite}.${CMAKE_MATCH_1}")
    if(NOT name IN_LIST excluded)
      if(NOT suite IN_LIST suites)
        list(APPEND suites "${suite}")
        set(count_${suite} 0)
      endif()
      math(EXPR count_${suite} "${count_${suite}} + 1")
    endif()
  endif()
endforeach()
set(text "")
foreach(suite IN LISTS suites)
  string(REPLACE "/" "_" file_name "${suite}")  # a parameterised suite's prefix
  string(APPEND text "add_test([=[${suite}]=] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${suite}.*:-${EXCLUDE}]==] "
         "[==[--gtest_output=xml:${XML_DIR}/${file_name}.xml]==])\n"
         "set_tests_properties([=[${suite}]=] PROPERTIES LABELS ${LABEL} TIMEOUT 1200 COST ${count_${suite}})\n")
endforeach()
file(WRITE "${OUT}" "${text}")
