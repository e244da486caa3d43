# Tests of the grader's isolation stage that are not part of the batches (included from
# grader/CMakeLists.txt beside tests/tests.cmake).
# A bubblewrap older than the sandbox's options (0.6.1, Ubuntu 22.04's) is named with the version
# needed; the old wording ("bwrap ended with exit code 1: ... Unknown option --size") fails it.
add_test(NAME "grade: a bubblewrap too old for the sandbox is named with the version needed"
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tests/isolation/old_bwrap.sh ${PROJECT_BINARY_DIR}/bin/t10-grade
                 ${PROJECT_SOURCE_DIR}/tutorial10_part1_tonemap ${CMAKE_CURRENT_BINARY_DIR}/test-out/old-bwrap)
set_tests_properties("grade: a bubblewrap too old for the sandbox is named with the version needed" PROPERTIES
                     SKIP_RETURN_CODE 77)
