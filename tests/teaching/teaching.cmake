# The teaching test: what each part does to the picture (tests/teaching/test_teaching.cpp).
# Included from tests/CMakeLists.txt, which has set BIN, DUMPS and EXPECT.
# Every stage renders the golden size at the camera presets the test measures; Part 0 also writes
# the EXR.
set(TEACHING_DUMPS ${DUMPS}/teaching)
add_executable(t10_teaching_tests teaching/test_teaching.cpp)
target_link_libraries(t10_teaching_tests PRIVATE t10_reference t10_flags t10_catch)

# "dark" shows no source: Parts 0 and 1 are enough for the exposure check. Each part's presets are the
# --then runs of one process (the driver, the shaders' code and the scene made once; the dumps are the
# same files as a process per preset writes: "capture: --then runs ..." checks that), 0.14 CPU s less
# a preset than a process each.
foreach(part part0_start part1_tonemap part2_bloom part3_gaussian)
    string(REGEX MATCH "^part[0-9]" short ${part})
    set(presets default lights)
    if(short STREQUAL "part0" OR short STREQUAL "part1")
        list(APPEND presets dark)
    endif()
    set(runs "")
    foreach(preset IN LISTS presets)
        set(dir ${TEACHING_DUMPS}/${short}_${preset})
        if(runs)
            list(APPEND runs --then)
        endif()
        list(APPEND runs --headless --backend egl --frames 1 --size 640x360 --camera ${preset} --dump ${dir}
                         --output ${dir}/frame.png)
        if(short STREQUAL "part0")
            list(APPEND runs --exr ${dir}/scene.exr)
        endif()
    endforeach()
    list(JOIN presets ", " names)
    add_test(NAME "dump: teaching ${short} ${names} (one process)" COMMAND ${BIN}/tutorial10_${part} ${runs})
    set_tests_properties("dump: teaching ${short} ${names} (one process)" PROPERTIES FIXTURES_SETUP teaching_dumps)
endforeach()

catch_discover_tests(t10_teaching_tests TEST_PREFIX "teaching: "
                     PROPERTIES FIXTURES_REQUIRED teaching_dumps ENVIRONMENT T10_DUMP_DIR=${TEACHING_DUMPS})

# The checks fail on the wrong stage's picture: each stage's frame posing as the next one's must
# fail the check that describes the next part, at that check.
# t10_add_teaching_reject(<stage shown> <stage claimed> <test case> <failing check regex>)
function(t10_add_teaching_reject shown claimed testcase check)
    add_test(NAME "teaching rejects: ${shown} posing as ${claimed}"
             COMMAND ${EXPECT} nonzero "${check}" -- ${CMAKE_COMMAND} -E env T10_DUMP_DIR=${TEACHING_DUMPS}
                     T10_TEACHING_POSE=${shown}:${claimed} $<TARGET_FILE:t10_teaching_tests> "${testcase}")
    set_tests_properties("teaching rejects: ${shown} posing as ${claimed}" PROPERTIES FIXTURES_REQUIRED teaching_dumps)
endfunction()

t10_add_teaching_reject(part0 part1 "Part 1 lifts the dark pixels and the darker view more"
                        "CHECK\\( lifts.back\\(\\) >= 1.5 \\)")
t10_add_teaching_reject(part1 part2 "Part 2 adds light around the sources and Part 3 spreads it twice as far"
                        "CHECK\\( bloom.bandMean >= 3.0 \\)")
t10_add_teaching_reject(part2 part3 "Part 2 adds light around the sources and Part 3 spreads it twice as far"
                        "CHECK\\( blur.rmsDistance >= 2.0 \\* bloom.rmsDistance \\)")
