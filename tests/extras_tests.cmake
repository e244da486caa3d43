# Tests of extras/ (the exercises, steps 37-40). Included from tests/CMakeLists.txt, which has set
# BIN, DUMPS, EXPECT and XVFB_RUN. The golden test ("golden: extras reproduces
# tutorial10_part3_gaussian") comes from stage_tests.cmake through SAME_GOLDEN_AS.
#
# Renders are small (256x256 scene, 128x128 and 64x64 inputs) and one frame each, so the whole file
# adds about half a minute on two cores.
if(NOT TARGET extras)
    return()
endif()

# --- Renders for the numeric checks (fixture extras_dumps; the inputs come from make_test_images). --

# t10_add_extras_dump(<name> <args...>): one frame of extras into ${DUMPS}/<name>/ (as t10_add_dump,
# but in a fixture of its own, so the other stages' numeric tests do not wait for these).
function(t10_add_extras_dump name)
    add_test(NAME "dump: ${name}"
             COMMAND ${BIN}/extras --headless --backend egl --frames 1 --camera default ${ARGN}
                     --dump ${DUMPS}/${name} --output ${DUMPS}/${name}/frame.png)
    # "dumps" too: the checks compare with Part 1 and Part 3 dumps, and catch_discover_tests cannot
    # pass them a list of fixtures, so they get those through these setup tests.
    set_tests_properties("dump: ${name}" PROPERTIES FIXTURES_SETUP extras_dumps
                         FIXTURES_REQUIRED "inputs;dumps")
endfunction()

set(SCENE --size 256x256)
t10_add_extras_dump(extras_default ${SCENE})
# Step 37: the white point (bloom off, so that only the tone map changes) and the bloom switch.
t10_add_extras_dump(extras_nobloom ${SCENE} --no-bloom)
t10_add_extras_dump(extras_yw010 ${SCENE} --no-bloom --white-point 0.1)
t10_add_extras_dump(extras_yw050 ${SCENE} --no-bloom --white-point 0.5)
t10_add_extras_dump(extras_yw100 ${SCENE} --no-bloom --white-point 1.0)
# Step 38: threshold (a multiple of Yw, also at another Yw) and strength.
t10_add_extras_dump(extras_thr100 ${SCENE} --bloom-threshold 1.0)
t10_add_extras_dump(extras_thr200 ${SCENE} --bloom-threshold 2.0)
t10_add_extras_dump(extras_thr400 ${SCENE} --bloom-threshold 4.0)
t10_add_extras_dump(extras_yw050_thr100 ${SCENE} --white-point 0.5 --bloom-threshold 1.0)
t10_add_extras_dump(extras_str000 ${SCENE} --bloom-strength 0)
t10_add_extras_dump(extras_str200 ${SCENE} --bloom-strength 2)
# Step 39: the hot pixel (128x128, tools/make_test_images) through 0 to 8 pass pairs.
foreach(n 0 1 2 3 5 8)
    t10_add_extras_dump(extras_hot_p${n} --input ${DUMPS}/inputs/hot.exr --blur-passes ${n})
endforeach()
# Step 40: GL_R16F where nothing exceeds Yw (the dim gradient, Yw 1) and in the scene (some pixels do).
t10_add_extras_dump(extras_dim_r16 --input ${DUMPS}/inputs/dim.exr --white-point 1.0)
t10_add_extras_dump(extras_dim_r16f --input ${DUMPS}/inputs/dim.exr --white-point 1.0 --luminance-format r16f)
# At the lamps view, where 3 % of the pixels exceed Yw by up to 2.6 in ln Y (the default view has
# fewer, and its clamp bias no longer stands clear of the R16F bound, see test_extras.cpp).
t10_add_extras_dump(extras_r16_lights ${SCENE} --camera lights)
t10_add_extras_dump(extras_r16f_lights ${SCENE} --camera lights --luminance-format r16f)
# --key exact at a size where Mesa's mip chain is off (320x180: 45 -> 22 -> 11 -> 5 rows).
t10_add_extras_dump(extras_key_exact --size 320x180 --key exact)
# The same check must reject the mip chain's key at that size (the dump goes under the name the
# test case reads, in a folder of its own).
add_test(NAME "dump: extras --key mip for the exact-key check"
         COMMAND ${BIN}/extras --headless --backend egl --frames 1 --camera default --size 320x180 --key mip
                 --dump ${DUMPS}/mutants/key_mip/extras_key_exact --output ${DUMPS}/mutants/key_mip/extras_key_exact/frame.png)
set_tests_properties("dump: extras --key mip for the exact-key check" PROPERTIES FIXTURES_SETUP extras_key_mip)

# --bench at a small size, its CSV read by the Catch2 test below.
add_test(NAME "dump: extras_bench"
         COMMAND ${EXPECT} 0 "post-process +[0-9.]+ +[0-9.]+ +[0-9.]+" --
                 ${BIN}/extras --headless --backend egl --size 160x90 --camera default --blur-passes 2 --bench 3
                 --bench-csv ${DUMPS}/extras_bench/bench.csv)
set_tests_properties("dump: extras_bench" PROPERTIES FIXTURES_SETUP extras_dumps)

add_executable(t10_extras_tests numeric/test_extras.cpp)
target_link_libraries(t10_extras_tests PRIVATE t10_reference t10_flags t10_catch)
# Part 1 and Part 3 dumps (fixture dumps, tests/CMakeLists.txt) are compared with extras' own.
catch_discover_tests(t10_extras_tests TEST_SPEC "~[window]" TEST_PREFIX "extras: "
                     PROPERTIES FIXTURES_REQUIRED extras_dumps ENVIRONMENT T10_DUMP_DIR=${DUMPS})

add_test(NAME "extras rejects: the mip chain's key where --key exact is checked"
         COMMAND ${EXPECT} nonzero "CHECK\\( relative <= bound \\)" -- ${CMAKE_COMMAND} -E env
                 T10_DUMP_DIR=${DUMPS}/mutants/key_mip ${BIN}/t10_extras_tests
                 "step 40: --key exact gives the exact log-average at a non-power-of-two size")
set_tests_properties("extras rejects: the mip chain's key where --key exact is checked"
                     PROPERTIES FIXTURES_REQUIRED extras_key_mip)

# --- Step 40: a non-finite scene key is reported, once. -------------------------------------------
# inf.exr / nan.exr put a non-finite log luminance into the GL_R16F chain (what the faulty hardware
# of exercise 40 produces; --keep-non-finite passes the pixels on, where --input would clamp them);
# three frames must give exactly one warning. GL_R16 clamps it: no warning.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/extras_key_warning.sh [=[
#!/bin/sh
# usage: extras_key_warning.sh EXPECTED_COUNT EXTRAS_ARGS...
expected=$1
shift
output=$("$@" 2>&1)
rc=$?
printf '%s\n' "$output"
count=$(printf '%s\n' "$output" | grep -c "warning: the scene key .* is \(NaN\|infinite\)")
echo "exit code $rc, $count warning(s), expected $expected"
[ "$rc" -eq 0 ] && [ "$count" -eq "$expected" ]
]=])
foreach(input inf nan)
    add_test(NAME "extras: r16f with a ${input} pixel warns once about the key"
             COMMAND sh ${CMAKE_CURRENT_BINARY_DIR}/extras_key_warning.sh 1 ${BIN}/extras --headless --backend egl
                     --frames 3 --input ${DUMPS}/inputs/${input}.exr --keep-non-finite --luminance-format r16f)
    add_test(NAME "extras: r16 with a ${input} pixel keeps a finite key"
             COMMAND sh ${CMAKE_CURRENT_BINARY_DIR}/extras_key_warning.sh 0 ${BIN}/extras --headless --backend egl
                     --frames 3 --input ${DUMPS}/inputs/${input}.exr --keep-non-finite)
    set_tests_properties("extras: r16f with a ${input} pixel warns once about the key"
                         "extras: r16 with a ${input} pixel keeps a finite key"
                         PROPERTIES FIXTURES_REQUIRED inputs)
endforeach()

# --- The command line: every option's bad values exit 2 with the allowed range. -----------------
foreach(case
        "--white-point;0.01;--white-point: must be from 0.05 to 2 \\(got 0.01\\)"
        "--white-point;9;--white-point: must be from 0.05 to 2 \\(got 9\\)"
        "--white-point;nan;--white-point: must be from 0.05 to 2"
        "--white-point;bright;--white-point: 'bright' is not a number; it must be from 0.05 to 2"
        "--bloom-threshold;0.4;--bloom-threshold: must be from 0.5 to 4 \\(got 0.4\\)"
        "--bloom-threshold;4.5;--bloom-threshold: must be from 0.5 to 4 \\(got 4.5\\)"
        "--bloom-strength;-1;--bloom-strength: must be from 0 to 4 \\(got -1\\)"
        "--bloom-strength;5;--bloom-strength: must be from 0 to 4 \\(got 5\\)"
        "--blur-passes;-1;--blur-passes: must be from 0 to 16 \\(got -1\\)"
        "--blur-passes;17;--blur-passes: must be from 0 to 16 \\(got 17\\)"
        "--blur-passes;2.5;--blur-passes: '2.5' is not a whole number; it must be from 0 to 16"
        "--luminance-format;r32f;--luminance-format: r32f not in \\{r16,r16f\\}"
        "--bench;0;--bench: must be from 1 to 100000 \\(got 0\\)"
        "--bench;many;--bench: 'many' is not a whole number; it must be from 1 to 100000")
    list(GET case 0 option)
    list(GET case 1 value)
    list(GET case 2 message)
    add_test(NAME "extras: cli rejects ${option} ${value}"
             COMMAND ${EXPECT} 2 "${message}" -- ${BIN}/extras --headless ${option} ${value})
endforeach()
add_test(NAME "extras: cli --bench-csv needs --bench"
         COMMAND ${EXPECT} 2 "--bench-csv requires --bench" -- ${BIN}/extras --headless --bench-csv x.csv)
add_test(NAME "extras: cli --no-bloom takes no value but true or false"
         COMMAND ${EXPECT} 2 "--no-bloom = maybe" -- ${BIN}/extras --headless --no-bloom=maybe)
add_test(NAME "extras: --help lists the options, their ranges and the keys"
         COMMAND ${EXPECT} 0 "--white-point.*0.05 to 2.*--bloom-threshold.*0.5 to 4.*--bloom-strength.*0 to 4.*--blur-passes.*0 to 16.*--luminance-format.*r16f.*Up / Down.*PageUp / PageDown.*L .*H "
                 -- sh -c "${BIN}/extras --help | tr '\\n' ' '")

# --- The window: panel, resizes and the rebuild it implies (Xvfb). -------------------------------
if(XVFB_RUN)
    t10_add_extras_dump(extras_640 --size 640x360)
    add_test(NAME "dump: extras_window"
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${EXPECT} 0 "wrote" --
                     ${BIN}/extras --backend window --size 640x360 --frames 3 --camera default
                     --output ${DUMPS}/extras_window/frame.png --dump ${DUMPS}/extras_window)
    set_tests_properties("dump: extras_window" PROPERTIES FIXTURES_SETUP extras_window)
    add_test(NAME "extras: the window shows the panel over the headless frame"
             COMMAND ${BIN}/t10_extras_tests "[window]")
    set_tests_properties("extras: the window shows the panel over the headless frame" PROPERTIES
                         FIXTURES_REQUIRED "extras_window;extras_dumps" ENVIRONMENT T10_DUMP_DIR=${DUMPS})
    # The panel is created in GL_Init and deleted in GL_Quit: a resize (0x0 included) rebuilds it.
    add_test(NAME "extras: window resizes, including 0x0, with the panel"
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${EXPECT} 0 "wrote" --
                     ${BIN}/extras --backend window --size 640x360 --frames 6
                     --resize-sequence 320x200,0x0,800x500,0x0,640x360 --output ${OUT}/window/extras_resized.png)
endif()
