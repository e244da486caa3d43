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
find_program(T10_EMCC emcc)
find_program(T10_CHROMIUM NAMES chromium chromium-browser)
set(T10_WEB_PAGES ${PROJECT_SOURCE_DIR}/out/web CACHE PATH "The web stages the browser tests load (make web)")
set(T10_WEB_BUILD ${PROJECT_SOURCE_DIR}/build-web CACHE PATH "The web build (emcmake cmake --preset web)")
set(WEB_TEST ${CMAKE_CURRENT_SOURCE_DIR}/web/web_test.py)
set(WEB_OUT ${CMAKE_CURRENT_BINARY_DIR}/web-out)
set(GOLDENS ${CMAKE_CURRENT_SOURCE_DIR}/golden)

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

# Every stage at the goldens' settings matches its golden and is told apart from its neighbours'.
set(parts ${T10_GOLDEN_STAGES})
list(LENGTH parts count)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
    list(GET parts ${i} stage)
    set(rejects "")
    if(i GREATER 0)
        math(EXPR before "${i} - 1")
        list(GET parts ${before} neighbour)
        list(APPEND rejects --reject ${neighbour})
    endif()
    if(i LESS last)
        math(EXPR after "${i} + 1")
        list(GET parts ${after} neighbour)
        list(APPEND rejects --reject ${neighbour})
    endif()
    t10_add_web_test("${stage} in Chromium matches its golden" golden ${stage} --golden ${stage} ${rejects})
endforeach()

if(TARGET extras)
    # The exercises' settings change the frame as the command line does: the defaults are Part 3's
    # frame; no blur passes read the bloom unblurred from level 0 (step 31), which is Part 1's frame
    # (measured with the binary: extras --blur-passes 0 against Part 1's golden, 0.0004% of pixels
    # over the threshold, mean 0.0004), not Part 2's (its bloom is read from the mipmapped level 1).
    t10_add_web_test("extras in Chromium matches tutorial10_part3_gaussian" golden extras
                     --golden tutorial10_part3_gaussian --reject tutorial10_part2_bloom)
    t10_add_web_test("extras ?blur-passes=0 matches tutorial10_part1_tonemap, as --blur-passes 0 does" golden extras
                     --name extras-blur0 --query blur-passes=0
                     --golden tutorial10_part1_tonemap --reject tutorial10_part2_bloom --reject tutorial10_part3_gaussian)
    t10_add_web_test("extras: Module.t10Set blur-passes 0 redraws Part 1's frame" live extras
                     --golden tutorial10_part3_gaussian --set blur-passes=0 --then tutorial10_part1_tonemap
                     --reject tutorial10_part3_gaussian)
endif()
# SwiftShader (its own tolerance: it cannot tell Part 1 from Part 2, see web-swiftshader.tolerance):
# the first and the last part, each against its golden, each rejecting its neighbour's.
t10_add_web_test("tutorial10_part0_start on SwiftShader matches its golden" golden tutorial10_part0_start
                 --name part0-swiftshader --renderer swiftshader --tolerance ${GOLDENS}/web-swiftshader.tolerance
                 --golden tutorial10_part0_start --reject tutorial10_part1_tonemap)
t10_add_web_test("tutorial10_part3_gaussian on SwiftShader matches its golden" golden tutorial10_part3_gaussian
                 --name part3-swiftshader --renderer swiftshader --tolerance ${GOLDENS}/web-swiftshader.tolerance
                 --golden tutorial10_part3_gaussian --reject tutorial10_part2_bloom)

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
t10_add_web_test("a student's Part 1 with a wrong white point fails the compare page" compare
                 student_t10test_planted_part1 --expect fail)
t10_add_web_test("a student's Part 1 copied from the reference passes the compare page" compare
                 student_t10test_fixed_part1 --expect pass)
foreach(verdict "a student's Part 1 with a wrong white point fails the compare page"
                "a student's Part 1 copied from the reference passes the compare page")
    set_tests_properties("web: ${verdict}" PROPERTIES FIXTURES_REQUIRED web_students)
endforeach()
