# Tests of the graders (included from grader/CMakeLists.txt, so CMAKE_CURRENT_SOURCE_DIR is grader/). The submissions are written at test
# time from the current reference stages by tests/make_submissions.py: each reference, a
# shaders-only copy of it and an equivalent rewrite must score 100, each known mistake must fail the
# check of its step with its diagnosis (and, with a value, the value measured within 10 %), Part 1
# with steps 6-10 missing must score below Part 1 with one wrong constant, each part's constant that
# no catalogue mistake names must score above the part with whole steps missing and never below the
# same constant with steps missing too (make_submissions.FAIR; issue 38), and broken submissions
# must get their status within the time limit. Renders are small
# (128x128, 160x90, 64x64) and the reference renders and built submissions are cached, so the part 3
# batch takes a few seconds of CPU per submission. Part 3's per-pass checks (blur-passes,
# blur-pass-count) are shown to fail on the tap, sigma, full_res_offsets, swapped_subroutines and
# pass_count submissions (check_reports.py), naming the first pass that goes wrong.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(EXPECT ${PROJECT_SOURCE_DIR}/tests/expect.sh)
set(GRADE_TESTS ${CMAKE_CURRENT_SOURCE_DIR}/tests)
set(GRADE_OUT ${CMAKE_CURRENT_BINARY_DIR}/test-out)
set(GRADE_SUBMISSIONS ${GRADE_OUT}/submissions)
set(GRADE_REPORTS ${GRADE_OUT}/reports)
set(GRADE_RUN ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${PROJECT_BINARY_DIR}/bin/t10-grade)
# The checks of the batches' reports skip with them (exit 77) where FLIP is not installed.
set(GRADE_CHECK ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${GRADE_TESTS}/check_reports.py)
# A render is killed after this many seconds; each takes one to three (ten on a loaded machine).
set(GRADE_TIMEOUT 20)
# The endless loop (make_submissions.py's loop) is graded alone under this limit (the batches would
# wait GRADE_TIMEOUT for it, the loop spinning a CPU all the while). It loops whatever the load.
set(GRADE_LOOP_TIMEOUT 3)

# The checks' core on buffers made in memory (core/test_core_in_memory.cpp), linked with the core alone:
# a page's readback would run the same checks. Each case says how it fails.
# It gives the core the catalogue compiled in, as a page would: mistakes.tsv as a string literal.
set(core_test_dir ${CMAKE_CURRENT_BINARY_DIR}/core_test)
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/diagnosis/mistakes.tsv mistakes_text)
file(WRITE ${core_test_dir}/mistakes_tsv.inc "R\"tsv(${mistakes_text})tsv\"\n")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/diagnosis/mistakes.tsv)
add_executable(t10_grade_core_tests ${GRADE_TESTS}/core/test_core_in_memory.cpp)
target_include_directories(t10_grade_core_tests PRIVATE ${core_test_dir})
target_link_libraries(t10_grade_core_tests PRIVATE t10_grade_core t10_flags t10_catch)
catch_discover_tests(t10_grade_core_tests TEST_PREFIX "grade core: ")

add_test(NAME "grade: write the test submissions"
         COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/make_submissions.py ${PROJECT_SOURCE_DIR} ${GRADE_SUBMISSIONS})
set_tests_properties("grade: write the test submissions" PROPERTIES FIXTURES_SETUP grade_submissions)

set(GRADE_PART3 reference3 shaders3 equivalent rec601 white_point threshold weight tap sigma no_unmapping log2_exp black_nan
    bloom_after full_res_offsets ceil_levels swapped_subroutines viewport_reset pass_count
    no_compile shader_error shader_bytes crash p3_unnamed_constant p3_unnamed_and_tone_map_missing p3_unnamed_and_bloom_missing)
set(GRADE_PART1 reference1 shaders1 equivalent1 p1_steps_missing p1_one_constant p1_middle_grey_1_0 p1_unnamed_constant
    p1_unnamed_and_steps_missing)
set(GRADE_PART2 reference2 shaders2 equivalent2 out_p2_no_mip_bias p2_one_change p2_change_and_step_missing p2_unnamed_constant
    p2_bloom_missing p2_unnamed_and_tone_map_missing)
# A sanitized build's submissions are built sanitized too: check_reports.py expects UBSan's report for
# the crash submission there.
if(T10_SANITIZE)
    set(GRADE_SANITIZED 1)
else()
    set(GRADE_SANITIZED 0)
endif()
# Part 3's batch also writes every platform's result (platforms.cmake checks them).
set(GRADE_FORMATS3 --format gradescope --format prairielearn --format classroom)
foreach(part 1 2 3)
    set(folders "")
    foreach(name IN LISTS GRADE_PART${part})
        list(APPEND folders ${GRADE_SUBMISSIONS}/part${part}/${name})
    endforeach()
    add_test(NAME "grade: part ${part} batch with --jobs 2"
             COMMAND ${GRADE_RUN} --part ${part} --jobs 2 --timeout ${GRADE_TIMEOUT} --fill-from-reference all ${GRADE_FORMATS${part}}
                     --report ${GRADE_REPORTS}/part${part} ${folders})
    # COST: ctest starts the long batches first, beside the many short tests (elsewhere: about ten times
    # a test's seconds, for a fresh clone, where ctest has no timing of an earlier run). Every later test that grades
    # a part in the default cache (build/grade-cache) requires its batch (grade_partN): the batch renders
    # and builds the reference once, where tests started beside it would each do it again.
    set_tests_properties("grade: part ${part} batch with --jobs 2" PROPERTIES COST 1000
                         FIXTURES_SETUP grade_part${part} FIXTURES_REQUIRED grade_submissions SKIP_RETURN_CODE 77)
    add_test(NAME "grade: part ${part} reports, scores and diagnoses"
             COMMAND ${GRADE_CHECK} reports ${GRADE_REPORTS}/part${part} ${GRADE_PART${part}})
    set_tests_properties("grade: part ${part} reports, scores and diagnoses" PROPERTIES FIXTURES_REQUIRED grade_part${part}
                         SKIP_RETURN_CODE 77 ENVIRONMENT "T10_GRADE_SANITIZED=${GRADE_SANITIZED}")
endforeach()

# The builds of that batch took the precompiled t10/app.hpp (grader/CMakeLists.txt): else each parses
# common/'s headers again, the same program 0.7 s of CPU later. Shown to fail with a header precompiled
# at -O1: "not used because `__OPTIMIZE__' not defined", in the kit's compile and in each build's log.
add_test(NAME "grade: the builds of submissions take the precompiled t10/app.hpp"
         COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE} ${GRADE_TESTS}/precompiled_check.py
                 ${T10_GRADE_HOST_KIT} ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/grade-cache/builds)
set_tests_properties("grade: the builds of submissions take the precompiled t10/app.hpp" PROPERTIES
                     FIXTURES_REQUIRED grade_part3 SKIP_RETURN_CODE 77)

# With it, a crash and a loop in the second case only (make_submissions.LATER): t10-grade renders the
# cases in one process, then the case it did not finish alone; the report must name that case (npot)
# and its own limit. Shown to fail when the failure is put on the first case instead ("case npot"
# missing from both messages).
add_test(NAME "grade: an endless loop is stopped at the time limit"
         COMMAND ${GRADE_RUN} --part 3 --jobs 2 --timeout ${GRADE_LOOP_TIMEOUT} --fill-from-reference all --report ${GRADE_REPORTS}/loop
                 ${GRADE_SUBMISSIONS}/part3/loop ${GRADE_SUBMISSIONS}/part3-later/crash_npot ${GRADE_SUBMISSIONS}/part3-later/loop_npot)
set_tests_properties("grade: an endless loop is stopped at the time limit" PROPERTIES
                     FIXTURES_SETUP grade_loop FIXTURES_REQUIRED "grade_submissions;grade_part3" SKIP_RETURN_CODE 77)
add_test(NAME "grade: the endless loop's report says timeout"
         COMMAND ${GRADE_CHECK} reports ${GRADE_REPORTS}/loop loop crash_npot loop_npot)
# crash_npot's null store is UBSan's report and exit 1 in a sanitized build, as the batches' crash is.
set_tests_properties("grade: the endless loop's report says timeout" PROPERTIES FIXTURES_REQUIRED grade_loop
                     SKIP_RETURN_CODE 77
                     ENVIRONMENT "T10_GRADE_LOOP_TIMEOUT=${GRADE_LOOP_TIMEOUT};T10_GRADE_SANITIZED=${GRADE_SANITIZED}")

# --- Fitted parameters (issue 20): every parameter of the catalogue at two values the batch above
# does not use, named with its value measured within 10 %, and mistakes outside the catalogue, which
# must fail with no name (check_reports.py reads the values from make_submissions.FITTED). Shown to
# fail on real reports of this batch: a value set 20 % away (white point 0.036 for 0.03) fails the
# 10 % test; a named submission listed as outside the catalogue fails "got names"; expecting another
# id fails "not named" and "wrong names beside"; a mistakes.tsv without an id fails "lacks"; Part 1's
# two reports swapped fail the steps-missing comparison (68 vs 93).
set(GRADE_FITTED fit_weights_a fit_weights_b fit_epsilon_a fit_epsilon_b fit_white_a fit_white_b fit_grey_a fit_grey_b
    fit_threshold_a fit_threshold_b fit_weight_a fit_weight_b fit_sigma_a fit_sigma_b fit_inner_a fit_inner_b
    fit_outer_a fit_outer_b fit_passes_a fit_passes_b fit_key_level_a fit_key_level_b
    out_gamma out_swizzle out_blur_centre out_threshold_max out_full_res_uv)
set(folders "")
foreach(name IN LISTS GRADE_FITTED)
    list(APPEND folders ${GRADE_SUBMISSIONS}/part3/${name})
endforeach()
add_test(NAME "grade: fitted parameters batch with --jobs 2"
         COMMAND ${GRADE_RUN} --part 3 --jobs 2 --timeout ${GRADE_TIMEOUT} --fill-from-reference all --report ${GRADE_REPORTS}/fitted ${folders})
set_tests_properties("grade: fitted parameters batch with --jobs 2" PROPERTIES COST 1000
                     FIXTURES_SETUP grade_fitted FIXTURES_REQUIRED "grade_submissions;grade_part3" SKIP_RETURN_CODE 77)
add_test(NAME "grade: fitted parameters named with their measured values"
         COMMAND ${GRADE_CHECK} reports ${GRADE_REPORTS}/fitted ${GRADE_FITTED})
set_tests_properties("grade: fitted parameters named with their measured values" PROPERTIES
                     FIXTURES_REQUIRED grade_fitted SKIP_RETURN_CODE 77)
# Every file t10-grade wrote for the batches above is valid UTF-8 (issue 38): report.json, report.html,
# the gradebooks, the class index and the platforms' results, with shader_bytes's compiler output and
# crash's program output holding bytes that are not UTF-8, control characters and markup. Shown to fail
# on main before the fix: shader_bytes/report.html held the bytes 0xe9 0xff 0xfe as they came.
add_test(NAME "grade: every file the grader wrote is valid UTF-8"
         COMMAND ${GRADE_CHECK} utf8 ${GRADE_REPORTS}/part1 ${GRADE_REPORTS}/part2 ${GRADE_REPORTS}/part3 ${GRADE_REPORTS}/fitted
                 ${GRADE_REPORTS}/loop)
set_tests_properties("grade: every file the grader wrote is valid UTF-8" PROPERTIES
                     FIXTURES_REQUIRED "grade_part1;grade_part2;grade_part3;grade_fitted;grade_loop" SKIP_RETURN_CODE 77)
# The instructors' page lists the catalogue (mistakes.tsv) as it is.
add_test(NAME "grade: the instructors' page lists mistakes.tsv"
         COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/check_reports.py docs ${PROJECT_SOURCE_DIR}/site/instructors.md)
# A faulty or missing rubric (T10_GRADE_RUBRIC): exit 1 with the file, the line and the fault.
file(WRITE ${GRADE_OUT}/bad-rubric.txt "default 1\n7 lots\n")
foreach(case "bad;${GRADE_OUT}/bad-rubric.txt;bad-rubric.txt:2: expected STEP POINTS"
             "missing;${GRADE_OUT}/no-such-rubric.txt;no-such-rubric.txt: cannot open the rubric: No such file or directory")
    list(GET case 0 label)
    list(GET case 1 rubric)
    list(GET case 2 regex)
    add_test(NAME "grade: ${label} rubric is refused"
             COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${EXPECT} 1 "${regex}" --
                     ${PROJECT_BINARY_DIR}/bin/t10-grade --part 1 --report ${GRADE_REPORTS}/rubric-${label}
                     ${GRADE_SUBMISSIONS}/part1/shaders1)
    set_tests_properties("grade: ${label} rubric is refused" PROPERTIES ENVIRONMENT "T10_GRADE_RUBRIC=${rubric}"
                         FIXTURES_REQUIRED grade_submissions SKIP_RETURN_CODE 77)
endforeach()
# --- end of the fitted parameters block.

# The batch graded in parallel gives the same gradebook rows as grading one at a time (a shader
# mistake, a host-code mistake and a submission that does not build).
set(single_gradebooks "")
foreach(name weight viewport_reset no_compile)
    add_test(NAME "grade: ${name} alone"
             COMMAND ${GRADE_RUN} --part 3 --timeout ${GRADE_TIMEOUT} --fill-from-reference all --report ${GRADE_REPORTS}/alone-${name}
                     ${GRADE_SUBMISSIONS}/part3/${name})
    set_tests_properties("grade: ${name} alone" PROPERTIES
                         FIXTURES_SETUP grade_alone FIXTURES_REQUIRED "grade_submissions;grade_part3" SKIP_RETURN_CODE 77)
    list(APPEND single_gradebooks ${GRADE_REPORTS}/alone-${name}/gradebook.csv)
endforeach()
add_test(NAME "grade: --jobs 2 gives the same gradebook as one by one"
         COMMAND ${GRADE_CHECK} same ${GRADE_REPORTS}/part3/gradebook.csv ${single_gradebooks})
set_tests_properties("grade: --jobs 2 gives the same gradebook as one by one" PROPERTIES
                     FIXTURES_REQUIRED "grade_part3;grade_alone" SKIP_RETURN_CODE 77)

# Bad usage exits 2 with a message naming the argument.
foreach(case
        "2;--part is required;${GRADE_SUBMISSIONS}"
        "2;--part 4: choose 1, 2 or 3;--part;4;${GRADE_SUBMISSIONS}"
        "2;no SUBMISSION folder given;--part;1"
        "2;/nonexistent-submission: not a folder;--part;1;/nonexistent-submission"
        "2;--jobs 0: expected a number from 1 to 64;--part;1;--jobs;0;${GRADE_SUBMISSIONS}"
        "2;unknown option --bogus;--part;1;--bogus"
        "2;--isolation bogus: choose auto, namespaces or uid;--part;1;--isolation;bogus;${GRADE_SUBMISSIONS}"
        "2;--fill-from-reference some: choose unchanged, all or none;--part;1;--fill-from-reference;some;${GRADE_SUBMISSIONS}"
        "2;would overwrite the submission;--part;1;--report;${PROJECT_SOURCE_DIR};${PROJECT_SOURCE_DIR}/tutorial10_part1_tonemap")
    list(POP_FRONT case code regex)
    string(REPLACE ";" " " label "${case}")
    add_test(NAME "grade: usage t10-grade ${label}" COMMAND ${EXPECT} ${code} "${regex}" -- ${PROJECT_BINARY_DIR}/bin/t10-grade ${case})
endforeach()

# --- t10-grade-tga grades a loader's source (tga.cpp) in the sandbox (tests/tga/tga_loaders.py writes
# the submissions from common/content/src/tga.cpp; the cheat and the attacks are in the hostile suite
# below). The project's loader scores 100 and each mutant (flip, swap, crash, hang, accept) fails the
# case it breaks with its verdict: shown to fail with a grader that counts every case as passed (each
# mutant "expected below 100 (got 100)").
set(GRADE_TGA_LOADERS ${Python3_EXECUTABLE} ${GRADE_TESTS}/tga/tga_loaders.py)
add_test(NAME "grade tga: the project's loader scores 100, each mutant fails with its verdict"
         COMMAND ${GRADE_TGA_LOADERS} mutants ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/bin/t10-grade-tga ${GRADE_OUT}/tga-mutants)
set_tests_properties("grade tga: the project's loader scores 100, each mutant fails with its verdict" PROPERTIES
                     SKIP_RETURN_CODE 77 COST 110)
foreach(case "2;the command mode is gone;tga2png {in} {out}" "2;/nonexistent-loader: not a folder;/nonexistent-loader"
             "2;--timeout 0: expected 1 to 600 seconds;--timeout;0;${PROJECT_SOURCE_DIR}")
    list(POP_FRONT case code regex)
    string(REPLACE ";" " " label "${case}")
    add_test(NAME "grade tga: usage t10-grade-tga ${label}" COMMAND ${EXPECT} ${code} "${regex}" -- ${PROJECT_BINARY_DIR}/bin/t10-grade-tga ${case})
endforeach()

# The copy-in: empty, README-only, wrong-case and odd files get their status and file list.
add_test(NAME "grade: submission files listed, empty and incomplete submissions get their status"
         COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/inputs_check.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/bin/t10-grade
                 ${T10_GRADE_VENV}/bin/flip ${GRADE_OUT}/inputs)
set_tests_properties("grade: submission files listed, empty and incomplete submissions get their status" PROPERTIES
                     FIXTURES_REQUIRED grade_part1 SKIP_RETURN_CODE 77)

# A checkout inside a 0700 folder (issue 29): as root the job uids cannot enter it; graded 100 with the
# namespaces isolation (staged copies), one line and grader-error with uid, and as the owning user. One
# test per case, each skipping (77) where it cannot run: wherever the checkout is (issue 38: from a clone
# directly under /tmp the handle on /tmp was kept inside /tmp, under the tmpfs; two levels below /root
# no user can own the folder, and the user case aborted t10-grade).
foreach(case root-namespaces root-uid user)
    add_test(NAME "grade: a checkout inside a 0700 folder (${case})"
             COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/private_checkout.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
                     ${GRADE_OUT}/private-checkout-${case} ${case})
    set_tests_properties("grade: a checkout inside a 0700 folder (${case})" PROPERTIES SKIP_RETURN_CODE 77 COST 30)
endforeach()

# The graders never abort (issue 38): a folder they may not enter (the report folder, a submission) ends
# in one handler: exit 1, one line naming the path and the system's reason, a grader-error result where
# the report folder can be written. Shown to fail on main before: exit -6, an uncaught filesystem_error.
add_test(NAME "grade: a folder the grader may not enter is one error line and a grader-error result, never an abort"
         COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/no_abort.py ${PROJECT_BINARY_DIR}/bin/t10-grade
                 ${PROJECT_BINARY_DIR}/bin/t10-grade-tga ${PROJECT_SOURCE_DIR} ${GRADE_OUT}/no-abort)
set_tests_properties("grade: a folder the grader may not enter is one error line and a grader-error result, never an abort"
                     PROPERTIES SKIP_RETURN_CODE 77)

# --- Hostile submissions (issues 19 and 29): each attack on the grader is contained, honest submissions
# graded beside them keep 100; the same for TGA loaders (hostile/tga_attacks.py), graded at the same
# time: the cheat (decodes the PNG beside its input: 100 with the command mode before issue 29) passes
# no valid case, and each attack is contained with its loader's 100 kept. Under namespaces where bwrap
# works, and under the uid fallback where the tests run as root; each skips (77) saying why elsewhere.
# The TGA part was shown to fail with the reference PNG copied beside the input in the case's folder
# (the cheat passes all 18 valid cases, read_reference reads it). One at a time: they count processes.
foreach(isolation namespaces uid)
    add_test(NAME "grade: hostile submissions are contained (${isolation})"
             COMMAND ${Python3_EXECUTABLE} ${GRADE_TESTS}/hostile/hostile.py ${isolation} ${PROJECT_SOURCE_DIR}
                     ${PROJECT_BINARY_DIR}/bin/t10-grade ${PROJECT_BINARY_DIR}/bin/t10-grade-tga ${T10_GRADE_VENV}/bin/flip
                     ${GRADE_OUT}/hostile-${isolation})
    set_tests_properties("grade: hostile submissions are contained (${isolation})" PROPERTIES
                         SKIP_RETURN_CODE 77 RESOURCE_LOCK grade_hostile COST 900 TIMEOUT 600)
endforeach()
# As a user other than root every sandbox runs as that user. The grader sets each sandbox's process limit
# inside its own user namespace, which Linux counts apart from the user's other processes since 5.14
# (issue 38; "grade: as a user, a fork bomb ..." proves it). On an older kernel the count is the user's,
# shared by every test: an attack that forks until refused could leave a render of another test beside
# it without a thread (seen as timeouts with an empty log), so there the hostile suites run alone.
execute_process(COMMAND id -u OUTPUT_VARIABLE T10_TEST_UID OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT T10_TEST_UID STREQUAL "0" AND CMAKE_HOST_SYSTEM_VERSION VERSION_LESS 5.14)
    set_tests_properties("grade: hostile submissions are contained (namespaces)" "grade: hostile submissions are contained (uid)"
                         PROPERTIES RUN_SERIAL TRUE)
endif()
# uid after namespaces: ctest starts a test others depend on before the rest, so the two (one at a time,
# about 35 s each) start early instead of last.
set_tests_properties("grade: hostile submissions are contained (uid)" PROPERTIES
                     DEPENDS "grade: hostile submissions are contained (namespaces)")
