# Tests of the platforms' results (formats.*), the class index (class_index.*) and the packaged scripts
# (platforms/), included from grader/CMakeLists.txt beside tests/tests.cmake, whose test submissions and
# settings (GRADE_*) they reuse. The part 3 batch of tests.cmake is graded with every --format; four of
# its submissions (correct, mistaken, not building, crashing) have each format validated against its
# platform's contract by tests/platforms/validate_*.py, and each validator is shown to reject broken
# results. The packaged Gradescope and PrairieLearn scripts run end to end in a scratch root, reusing
# this build and the grader's cache.
set(PLATFORM_TESTS ${GRADE_TESTS}/platforms)
set(PLATFORM_OUT ${GRADE_OUT}/platforms)
set(PLATFORM_SUBMISSIONS reference3 weight no_compile crash)
set(PLATFORM_BATCH ${GRADE_REPORTS}/part3)

set(PLATFORM_CHECK ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/check_platforms.py)
foreach(format gradescope prairielearn classroom)
    add_test(NAME "grade platforms: ${format} results valid for a correct, a mistaken, a non-building and a crashing submission"
             COMMAND ${PLATFORM_CHECK} results ${format} ${PLATFORM_BATCH} ${PLATFORM_SUBMISSIONS})
    set_tests_properties("grade platforms: ${format} results valid for a correct, a mistaken, a non-building and a crashing submission"
                         PROPERTIES FIXTURES_REQUIRED grade_part3 SKIP_RETURN_CODE 77)
endforeach()
add_test(NAME "grade platforms: the validators reject broken results"
         COMMAND ${PLATFORM_CHECK} rejects ${PLATFORM_BATCH}/weight)
set_tests_properties("grade platforms: the validators reject broken results" PROPERTIES FIXTURES_REQUIRED grade_part3
                     SKIP_RETURN_CODE 77)

# The grader's own failure (a cache folder it cannot create): exit 1, and every platform still gets a
# result (PrairieLearn: gradable false).
add_test(NAME "grade platforms: the grader's failure is written as not gradable"
         COMMAND ${PLATFORM_TESTS}/grader_error.sh ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip
                 ${PROJECT_BINARY_DIR}/bin/t10-grade ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/check_platforms.py
                 ${GRADE_SUBMISSIONS}/part3/weight ${PLATFORM_OUT}/grader-error)
set_tests_properties("grade platforms: the grader's failure is written as not gradable" PROPERTIES
                     FIXTURES_REQUIRED grade_submissions SKIP_RETURN_CODE 77)

foreach(platform gradescope prairielearn)
    add_test(NAME "grade platforms: ${platform} scripts end to end in a scratch root"
             COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/platform_e2e.py
                     ${platform} ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR} ${GRADE_SUBMISSIONS}/part3/weight ${PLATFORM_OUT}/${platform})
    # The test submission (weight) holds only the shader its mistake changes: the rest from the reference.
    set_tests_properties("grade platforms: ${platform} scripts end to end in a scratch root" PROPERTIES
                         FIXTURES_REQUIRED "grade_submissions;grade_part3" SKIP_RETURN_CODE 77 ENVIRONMENT "T10_FILL_FROM_REFERENCE=all" COST 40)
endforeach()

add_test(NAME "grade platforms: a class named from a path component or a roster, its index and LMS CSV"
         COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/check_class.py
                 ${PROJECT_BINARY_DIR}/bin/t10-grade ${GRADE_SUBMISSIONS} ${PLATFORM_OUT}/class)
set_tests_properties("grade platforms: a class named from a path component or a roster, its index and LMS CSV" PROPERTIES
                     FIXTURES_REQUIRED "grade_submissions;grade_part3" SKIP_RETURN_CODE 77 COST 80)

# Usage: --format and --name-from refuse what they cannot do.
foreach(case
        "2;--format pdf: choose gradescope, prairielearn or classroom;--part;3;--format;pdf;${PROJECT_SOURCE_DIR}/tutorial10_part3_gaussian"
        "2;--name-from \\(: not a component index nor a valid regular expression;--part;3;--name-from;(;${PROJECT_SOURCE_DIR}/tutorial10_part3_gaussian"
        "2;--roster /nonexistent.csv: cannot open: No such file;--part;3;--roster;/nonexistent.csv;${PROJECT_SOURCE_DIR}/tutorial10_part3_gaussian")
    list(POP_FRONT case code regex)
    string(REPLACE ";" " " label "${case}")
    add_test(NAME "grade platforms: usage t10-grade ${label}" COMMAND ${EXPECT} ${code} "${regex}" -- ${PROJECT_BINARY_DIR}/bin/t10-grade ${case})
endforeach()

# The platforms' install script (setup.sh, the Dockerfile) decides right for each release's packages:
# played by stand-ins for apt-get, apt-cache, bwrap and cmake, so nothing is installed.
add_test(NAME "grade platforms: install_grader.sh builds on Ubuntu 22.04 (CMake from PyPI), refuses an older release"
         COMMAND ${PLATFORM_TESTS}/install_check.sh ${PROJECT_SOURCE_DIR} ${PLATFORM_OUT}/install-check)
# The OpenEXR package that install_grader.sh lets through on Ubuntu 22.04 (2.5, OpenEXR::IlmImf) is the
# one cmake/T10OpenEXR.cmake takes: played by stand-in config packages of 3, 2.5 and a too old 2.3.
add_test(NAME "grade platforms: cmake/T10OpenEXR.cmake takes OpenEXR 3 and 2.5 (Ubuntu 22.04), refuses 2.3"
         COMMAND ${PLATFORM_TESTS}/openexr_package_check.sh ${PROJECT_SOURCE_DIR} ${PLATFORM_OUT}/openexr-package-check)

# The students' GitHub Classroom workflow parses as YAML and has the shape the Classroom reporter needs;
# the grading step's outputs, run through GitHub Classroom's released reporter, show what a student reads.
add_test(NAME "grade platforms: the Classroom workflow is valid YAML with the reporter wired"
         COMMAND ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/check_workflow.py yaml ${PROJECT_SOURCE_DIR}/.github/workflows/grade.yml)
add_test(NAME "grade platforms: the Classroom workflow's grading step merges parts, writes the job summary"
         COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${PLATFORM_TESTS}/check_workflow.py
                 grade ${PROJECT_BINARY_DIR}/bin/t10-grade ${GRADE_SUBMISSIONS} ${PLATFORM_OUT}/workflow)
set_tests_properties("grade platforms: the Classroom workflow's grading step merges parts, writes the job summary" PROPERTIES
                     FIXTURES_REQUIRED "grade_submissions;grade_part1;grade_part3" SKIP_RETURN_CODE 77 COST 40)
