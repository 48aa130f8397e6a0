# Registers one ctest test per GoogleTest suite of EXECUTABLE (run after each build of it):
#   cmake -D EXECUTABLE=... -D PREFIX=module. -D LABEL=unit -D TIMEOUT=120 -D WORKING_DIRECTORY=...
#         -D OUTPUT=suites.cmake -P LittermapTestSuites.cmake
# A test process costs ~0.15 s before its first test runs (OpenCV's image codecs load GDAL and a
# hundred more shared libraries), which is most of a unit test's time; one process per suite keeps
# the unit tier at the speed of its tests. ctest names the suite (module.Suite) and, on failure,
# prints GoogleTest's output naming the test.
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE result ERROR_VARIABLE errors
                TIMEOUT 60)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${result}): ${errors}")
endif()

string(REPLACE "\n" ";" lines "${listing}")
set(script "")
foreach(line IN LISTS lines)
  # Suites are the unindented lines, "Suite." or "Instance/Suite.  # TypeParam = ..."
  if(line MATCHES "^([^ #][^ ]*)\\.")
    set(suite "${CMAKE_MATCH_1}")
    string(APPEND script
           "add_test([=[${PREFIX}${suite}]=] [==[${EXECUTABLE}]==] [==[--gtest_filter=${suite}.*]==])\n"
           "set_tests_properties([=[${PREFIX}${suite}]=] PROPERTIES LABELS ${LABEL} TIMEOUT ${TIMEOUT}"
           " WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==])\n")
  endif()
endforeach()
file(WRITE "${OUTPUT}" "${script}")
