# The web stages in headless Chromium (tests/web/web_test.py), against the same goldens as the
# binaries. Included from tests/CMakeLists.txt. The pages are built by `make web` (emscripten, into
# T10_WEB_PAGES); `make test` builds them before ctest runs. Registered only where both emscripten
# (emcc) and Chromium are installed; elsewhere one test reports itself skipped (77) and says why.
#
# Renderers: Chromium's WebGL runs on ANGLE. With its GL ES backend on Mesa (--use-angle=gl-egl) it
# rasterises with llvmpipe, as the goldens were rendered: every test runs there, under
# tests/golden/web.tolerance. On SwiftShader (--use-angle=swiftshader, headless Chromium's own) the
# first and last parts run too, under tests/golden/web-swiftshader.tolerance (looser: another
# rasteriser). Each tolerance file gives its measurements and reasons.
#
# Firefox ESR, the second engine: one Firefox on its own Xvfb display (headless Firefox has no WebGL
# here) loads the five stage pages in turn, driven over Marionette (tools/web/marionette.py). Its WebGL
# runs on Mesa llvmpipe without ANGLE; the frames match the goldens under web.tolerance (measured there).
# Registered with or without Chromium; it skips (77), saying why, without emscripten, Firefox or Xvfb.
find_program(T10_EMCC emcc)
find_program(T10_CHROMIUM NAMES chromium chromium-browser)
find_program(T10_FIREFOX NAMES firefox-esr firefox)
find_program(T10_XVFB Xvfb)
set(T10_WEB_PAGES ${PROJECT_SOURCE_DIR}/out/web CACHE PATH "The web stages the browser tests load (make web)")
set(T10_WEB_BUILD ${PROJECT_SOURCE_DIR}/build-web CACHE PATH "The web build (emcmake cmake --preset web)")
set(WEB_TEST ${CMAKE_CURRENT_SOURCE_DIR}/web/web_test.py)
set(WEB_OUT ${CMAKE_CURRENT_BINARY_DIR}/web-out)
set(GOLDENS ${CMAKE_CURRENT_SOURCE_DIR}/golden)

# Each stage's neighbours, whose goldens its frame must not match (the tests can fail): t10_rejects_<stage>.
set(parts ${T10_GOLDEN_STAGES})
list(LENGTH parts count)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
    list(GET parts ${i} stage)
    set(t10_rejects_${stage} "")
    foreach(step -1 1)
        math(EXPR j "${i} + ${step}")
        if(j GREATER_EQUAL 0 AND j LESS_EQUAL last)
            list(GET parts ${j} neighbour)
            list(APPEND t10_rejects_${stage} ${neighbour})
        endif()
    endforeach()
endforeach()

set(firefox_test "web: the stage pages in Firefox ESR (Xvfb) match their goldens")
set(missing "")
foreach(need T10_EMCC T10_FIREFOX T10_XVFB)
    if(NOT ${need})
        string(APPEND missing " ${need}")
    endif()
endforeach()
if(missing)
    add_test(NAME "${firefox_test}"
             COMMAND sh -c "echo 'SKIP: not found:${missing} (apt-get install emscripten firefox-esr xvfb; make test installs them on Debian)' >&2; exit 77")
else()
    # Every stage against its golden, rejecting its neighbours'; extras' defaults draw Part 3's frame.
    set(cases "")
    foreach(stage ${parts})
        list(JOIN t10_rejects_${stage} "," rejects)
        list(APPEND cases --case ${stage} ${stage} ${rejects})
    endforeach()
    if(TARGET extras)
        list(APPEND cases --case extras tutorial10_part3_gaussian tutorial10_part2_bloom)
    endif()
    add_test(NAME "${firefox_test}"
             COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${WEB_TEST} goldens --browser firefox --firefox ${T10_FIREFOX}
                     --web ${T10_WEB_PAGES} --imgcompare $<TARGET_FILE:imgcompare> --goldens ${GOLDENS}
                     --out ${WEB_OUT}/firefox --timeout 180 ${cases})
endif()
# 19 s alone on two cores (one Firefox start, five pages); the bounds leave room for make test's load.
set_tests_properties("${firefox_test}" PROPERTIES TIMEOUT 240 LABELS web SKIP_RETURN_CODE 77)

set(missing "")
if(NOT T10_EMCC)
    string(APPEND missing " emscripten (emcc)")
endif()
if(NOT T10_CHROMIUM)
    string(APPEND missing " chromium")
endif()
if(missing)
    add_test(NAME "web: the stages in Chromium"
             COMMAND sh -c "echo 'SKIP: the web tests need${missing}: apt-get install emscripten chromium (make test installs them)' >&2; exit 77")
    set_tests_properties("web: the stages in Chromium" PROPERTIES SKIP_RETURN_CODE 77)
    return()
endif()

set(WEB_COMMON --web ${T10_WEB_PAGES} --chromium ${T10_CHROMIUM} --imgcompare $<TARGET_FILE:imgcompare>
               --goldens ${GOLDENS})

# t10_add_web_test(<name> <command> <stage> [args...]): one page in its own Chromium.
function(t10_add_web_test name command stage)
    string(MAKE_C_IDENTIFIER "${name}" folder)
    add_test(NAME "web: ${name}"
             COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${WEB_TEST} ${command} ${WEB_COMMON} --stage ${stage}
                     --out ${WEB_OUT}/${folder} ${ARGN})
    set_tests_properties("web: ${name}" PROPERTIES TIMEOUT 200 LABELS web SKIP_RETURN_CODE 77)
endfunction()

# Every stage at the goldens' settings matches its golden and is told apart from its neighbours', in
# one Chromium (web_test.py goldens: every page judged, then every failure listed): a browser per page
# cost about 1.4 s of CPU each (starting Chromium and its GPU process), 13.3 s for the five pages alone
# and 6.5 s in one browser. The exercises' settings change the frame as the command line does: extras'
# defaults are Part 3's frame; no blur passes read the bloom unblurred from level 0 (step 31), which is
# Part 1's frame (measured with the binary: extras --blur-passes 0 against Part 1's golden, 0.0004% of
# pixels over the threshold, mean 0.0004), not Part 2's (its bloom is read from the mipmapped level 1).
set(cases "")
foreach(stage ${parts})
    list(JOIN t10_rejects_${stage} "," rejects)
    list(APPEND cases --case ${stage} ${stage} ${rejects})
endforeach()
if(TARGET extras)
    list(APPEND cases --case extras tutorial10_part3_gaussian tutorial10_part2_bloom
                      --case "extras?blur-passes=0" tutorial10_part1_tonemap tutorial10_part2_bloom,tutorial10_part3_gaussian)
endif()
add_test(NAME "web: the stage pages in Chromium match their goldens (extras also with ?blur-passes=0)"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${WEB_TEST} goldens ${WEB_COMMON} --out ${WEB_OUT}/chromium-goldens
                 --timeout 180 ${cases})
set_tests_properties("web: the stage pages in Chromium match their goldens (extras also with ?blur-passes=0)" PROPERTIES
                     TIMEOUT 240 LABELS web SKIP_RETURN_CODE 77)
if(TARGET extras)
    t10_add_web_test("extras: Module.t10Set blur-passes 0 redraws Part 1's frame" live extras
                     --golden tutorial10_part3_gaussian --set blur-passes=0 --then tutorial10_part1_tonemap
                     --reject tutorial10_part3_gaussian)
endif()
# SwiftShader (its own tolerance: it cannot tell Part 1 from Part 2, see web-swiftshader.tolerance):
# the first and the last part, each against its golden, each rejecting its neighbour's, in one Chromium.
add_test(NAME "web: Parts 0 and 3 on SwiftShader match their goldens"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${WEB_TEST} goldens ${WEB_COMMON} --out ${WEB_OUT}/swiftshader-goldens
                 --renderer swiftshader --tolerance ${GOLDENS}/web-swiftshader.tolerance --timeout 180
                 --case tutorial10_part0_start tutorial10_part0_start tutorial10_part1_tonemap
                 --case tutorial10_part3_gaussian tutorial10_part3_gaussian tutorial10_part2_bloom)
set_tests_properties("web: Parts 0 and 3 on SwiftShader match their goldens" PROPERTIES
                     TIMEOUT 240 LABELS web SKIP_RETURN_CODE 77)

# The page's workbench contract (tests/web/workbench_test.py): Parts 1-3 in one Chromium, one page load
# each; Module.t10Shaders lists the stage's files, t10SetShader answers errors on the student's line
# and keeps the last good program drawing, a wrong edit leaves the golden (and Module.t10Check names
# it with its value), the reference's own files bring the golden back and Module.t10Check scores them
# 100. About 14 s alone on two cores.
set(workbench_test "web: Module.t10SetShader and t10Check on Parts 1-3: errors on the student's line, the reference's shaders match the goldens and score 100")
set(cases "")
foreach(stage ${parts})
    if(NOT stage STREQUAL "tutorial10_part0_start")
        list(APPEND cases --case ${stage})
    endif()
endforeach()
add_test(NAME "${workbench_test}"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/web/workbench_test.py
                 --web ${T10_WEB_PAGES} --chromium ${T10_CHROMIUM} --imgcompare $<TARGET_FILE:imgcompare>
                 --goldens ${GOLDENS} --source ${PROJECT_SOURCE_DIR} --out ${WEB_OUT}/workbench ${cases})
set_tests_properties("${workbench_test}" PROPERTIES TIMEOUT 200 LABELS web SKIP_RETURN_CODE 77)

# The page's check agrees with t10-grade (tests/web/agreement.py) on a representative set of the grader
# batches' shader-only mistakes, one per shader file of Part 3 (one page load), graded by the batch test
# (grade_part3): the luminance weights (Rec. 601, PostProcessInit.frag), the white point
# (PostProcess.frag) and the blur's sigma (Gauss.frag): the same checks fail, the same mistake is named,
# its value within 1 %, the score within 2 points. Every shader-only submission of the three batches
# (33): make web-agreement.
set(agreement_test "web: Module.t10Check agrees with t10-grade on Rec. 601 weights, a white point and a sigma")
set(GRADE_TEST_OUT ${PROJECT_BINARY_DIR}/grader/test-out)
add_test(NAME "${agreement_test}"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/web/agreement.py
                 --web ${T10_WEB_PAGES} --chromium ${T10_CHROMIUM} --source ${PROJECT_SOURCE_DIR}
                 --submissions ${GRADE_TEST_OUT}/submissions --reports ${GRADE_TEST_OUT}/reports --out ${WEB_OUT}/agreement
                 --case 3 rec601 --case 3 white_point --case 3 sigma)
set_tests_properties("${agreement_test}" PROPERTIES TIMEOUT 200 LABELS web SKIP_RETURN_CODE 77
                     FIXTURES_REQUIRED grade_part3)

# The same on SwiftShader (what Chromium without a GPU draws with), Part 3's sigma alone: the reference's
# shaders must score 100 there (--reference-score; they scored 94 while the blur's checks modelled Mesa's
# R11G11B10F store only, which SwiftShader's half-float rounding missed by 1.8e-4 of the peak) and the
# sigma mistake is still caught and agrees. About 5 s.
set(swiftshader_test "web: on SwiftShader Part 3's reference scores 100 and Module.t10Check agrees with t10-grade on a sigma")
add_test(NAME "${swiftshader_test}"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/web/agreement.py
                 --web ${T10_WEB_PAGES} --chromium ${T10_CHROMIUM} --source ${PROJECT_SOURCE_DIR}
                 --submissions ${GRADE_TEST_OUT}/submissions --reports ${GRADE_TEST_OUT}/reports
                 --out ${WEB_OUT}/agreement-swiftshader --renderer swiftshader --reference-score 100 --case 3 sigma)
set_tests_properties("${swiftshader_test}" PROPERTIES TIMEOUT 200 LABELS web SKIP_RETURN_CODE 77
                     FIXTURES_REQUIRED grade_part3)

# A browser without float render targets gets the message, not a black canvas.
t10_add_web_test("without EXT_color_buffer_float the page says so" nofloat tutorial10_part1_tonemap)

# The compare page of a student's build: two student stages of the web build (cmake/T10WebCompare.cmake,
# t10_web_compare_test_students), a copy of Part 1 with a wrong white point and a plain copy, built
# here into the web build (the step that needs emscripten; NODE_PATH as the Makefile's make web sets it:
# Debian's emscripten finds its Node modules there), then judged by their ?compare=1 pages.
add_test(NAME "web: build the compare test's student stages"
         COMMAND sh -c "if [ ! -f \"$1/build.ninja\" ]; then echo \"SKIP: $1 is not configured: make web configures it\" >&2; exit 77; fi; NODE_PATH=\"\${NODE_PATH:-/usr/share/nodejs}\" exec \"$0\" --build \"$1\" --target t10_web_compare_test_students"
                 ${CMAKE_COMMAND} ${T10_WEB_BUILD})
set_tests_properties("web: build the compare test's student stages" PROPERTIES
                     FIXTURES_SETUP web_students TIMEOUT 300 LABELS web SKIP_RETURN_CODE 77)
# Both pages in one Chromium (web_test.py compares: each judged, then every failure listed): 7.4 CPU s
# as two tests with a browser each, 5.7 s as one.
set(compare_test "web: a student's Part 1 with a wrong white point fails the compare page, a copy of the reference passes")
add_test(NAME "${compare_test}"
         COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${WEB_TEST} compares ${WEB_COMMON} --out ${WEB_OUT}/compare
                 --verdict student_t10test_planted_part1 fail --verdict student_t10test_fixed_part1 pass)
set_tests_properties("${compare_test}" PROPERTIES TIMEOUT 200 LABELS web SKIP_RETURN_CODE 77 FIXTURES_REQUIRED web_students)

# Issue 50's embeds (tests/web/embeds_test.py): each fault the issue found, on Part 0, Part 3 and extras
# (every check failed on the pages before the fix: the script's text quotes how), and a share of the
# hostile queries, one or two of each kind, on Part 0: about 11 s alone on two cores. All 50 queries on
# every stage page take about 85 s (250 page loads), so they run in make site-audit (label audit; .ci/run
# runs it after make web), not in make test.
set(EMBEDS_TEST ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/web/embeds_test.py
                --web ${T10_WEB_PAGES} --chromium ${T10_CHROMIUM})
add_test(NAME "web: the embeds' faults are fixed, and hostile queries reach a verdict (a share, Part 0)"
         COMMAND ${EMBEDS_TEST} --out ${WEB_OUT}/embeds --faults --stage tutorial10_part0_start --queries quick)
set_tests_properties("web: the embeds' faults are fixed, and hostile queries reach a verdict (a share, Part 0)"
                     PROPERTIES TIMEOUT 120 LABELS web SKIP_RETURN_CODE 77)
set(stages "")
foreach(stage ${parts})
    list(APPEND stages --stage ${stage})
endforeach()
if(TARGET extras)
    list(APPEND stages --stage extras)
endif()
add_test(NAME "web: 50 hostile queries on every stage page each reach a verdict within 10 s"
         COMMAND ${EMBEDS_TEST} --out ${WEB_OUT}/embeds-all --queries all ${stages})
set_tests_properties("web: 50 hostile queries on every stage page each reach a verdict within 10 s"
                     PROPERTIES TIMEOUT 400 LABELS "web;audit" SKIP_RETURN_CODE 77)
