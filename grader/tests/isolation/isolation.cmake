# Tests of the grader's isolation stage that are not part of the batches (included from
# grader/CMakeLists.txt beside tests/tests.cmake).
# A bubblewrap older than the sandbox's options (0.6.1, Ubuntu 22.04's) is named with the version
# needed; the old wording ("bwrap ended with exit code 1: ... Unknown option --size") fails it.
add_test(NAME "grade: a bubblewrap too old for the sandbox is named with the version needed"
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tests/isolation/old_bwrap.sh ${PROJECT_BINARY_DIR}/bin/t10-grade
                 ${PROJECT_SOURCE_DIR}/tutorial10_part1_tonemap ${CMAKE_CURRENT_BINARY_DIR}/test-out/old-bwrap)
set_tests_properties("grade: a bubblewrap too old for the sandbox is named with the version needed" PROPERTIES
                     SKIP_RETURN_CODE 77)

# Jobs that cannot starve each other (issue 38): a Part 1 that forks until refused, graded as a user
# other than root beside two honest copies with --jobs 2; every honest copy scores 100 and every bomb is
# held to its job's 64 processes. Two rounds here; `make grade-jobs-check` runs twenty (.ci/run). Shown
# to fail with the grader from before (one process count for all of a user's jobs): honest copies timed
# out ("the program timed out after 60 s") beside the bomb.
add_test(NAME "grade: as a user, a fork bomb beside honest submissions (--jobs 2) starves none of them"
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/tests/isolation/fork_bomb_jobs.py ${PROJECT_SOURCE_DIR}
                 ${PROJECT_BINARY_DIR}/bin/t10-grade ${T10_GRADE_VENV}/bin/flip ${CMAKE_CURRENT_BINARY_DIR}/test-out/fork-bomb-jobs 2)
set_tests_properties("grade: as a user, a fork bomb beside honest submissions (--jobs 2) starves none of them" PROPERTIES
                     SKIP_RETURN_CODE 77 COST 150 TIMEOUT 600)
