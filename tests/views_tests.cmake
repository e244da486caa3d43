# Tests of the view selector (common/frame/src/views/views.cpp, --view). Included from tests/CMakeLists.txt,
# which has set BIN, DUMPS, EXPECT and T10_STAGES.
#
# Every view of every stage renders one small frame without a GL error (a GL error fails the run),
# every view a stage lacks is refused with exit 2 and the exact list of the views it has, and a
# Catch2 program decodes the images the views wrote against what they show. 160x90 keeps the ~50
# renders at about a second each on two cores.
set(VIEWS ${CMAKE_CURRENT_BINARY_DIR}/views)
set(VIEW_ARGS --headless --backend egl --frames 1 --camera default --size 160x90)
set(ALL_VIEWS final hdr luminance key bloom0 bloom1 blur ev nan)

# The views each stage has, in the order --help lists them.
set(VIEWS_OF_tutorial10_part0_start final hdr nan)
set(VIEWS_OF_tutorial10_part1_tonemap final hdr luminance key ev nan)
set(VIEWS_OF_tutorial10_part2_bloom final hdr luminance key bloom0 bloom1 ev nan)
set(VIEWS_OF_tutorial10_part3_gaussian final hdr luminance key bloom0 bloom1 blur ev nan)
set(VIEWS_OF_extras ${VIEWS_OF_tutorial10_part3_gaussian})

# A stage added to T10_STAGES without a list here (a copied folder, a new stage in the making) gets the
# views every stage has, rendered, and no refusal tests: which views it lacks is not known until it is
# listed. (A student's own version of a part belongs in student/, built without T10_STAGES: `make student`.)
set(VIEWS_OF_EVERY_STAGE final hdr nan)

# A listed stage renders all its views in one process, a run each (the stages' --then: the driver and
# the scene are made once; what each run writes is what a process of its own writes, the test "capture:
# --then runs ..." shows it): Part 3's nine views 0.51 CPU s instead of 1.36. A run that fails, or
# cannot write an output, fails the process, and the checks below decode every image. Stages with
# options of their own refuse --then (runStage): one process per view, as unlisted stages get too.
set(VIEWS_ONE_PROCESS_EACH extras)

foreach(stage IN LISTS T10_STAGES)
    set(listed TRUE)
    if(NOT DEFINED VIEWS_OF_${stage})
        message(STATUS "views_tests.cmake: stage ${stage} has no view list (VIEWS_OF_${stage}): only the views "
                       "every stage has (${VIEWS_OF_EVERY_STAGE}) are tested for it")
        set(VIEWS_OF_${stage} ${VIEWS_OF_EVERY_STAGE})
        set(listed FALSE)
    endif()
    set(then_runs "")
    set(then_views "")
    string(REPLACE ";" ", " has "${VIEWS_OF_${stage}}")
    foreach(view IN LISTS ALL_VIEWS)
        if(NOT listed AND NOT view IN_LIST VIEWS_OF_${stage})
            continue()
        endif()
        if(view IN_LIST VIEWS_OF_${stage})
            # The image, the stage's textures (for the checks) and the caption line on stdout.
            set(run ${VIEW_ARGS} --view ${view} --output ${VIEWS}/${stage}/${view}/frame.png --dump ${VIEWS}/${stage}/${view})
            if(listed AND NOT stage IN_LIST VIEWS_ONE_PROCESS_EACH)
                if(then_runs)
                    list(APPEND then_runs --then)
                endif()
                list(APPEND then_runs ${run})
                list(APPEND then_views ${view})
                continue()
            endif()
            add_test(NAME "view: ${stage} ${view}"
                     COMMAND ${EXPECT} 0 "^wrote ${VIEWS}/${stage}/${view}/frame.png" -- ${BIN}/${stage} ${run})
            set_tests_properties("view: ${stage} ${view}" PROPERTIES FIXTURES_SETUP views)
        else()
            add_test(NAME "view: ${stage} refuses ${view}"
                     COMMAND ${EXPECT} 2 "--view ${view}: this stage has no ${view} \\(its views: ${has}\\)" --
                             ${BIN}/${stage} ${VIEW_ARGS} --view ${view} --output ${VIEWS}/refused.png)
        endif()
    endforeach()
    if(then_views)
        # The last run's line: the runs go in order and the first that fails ends the process.
        list(GET then_views -1 last)
        string(REPLACE ";" ", " names "${then_views}")
        add_test(NAME "view: ${stage} ${names} (one process)"
                 COMMAND ${EXPECT} 0 "^wrote ${VIEWS}/${stage}/${last}/frame.png" -- ${BIN}/${stage} ${then_runs})
        set_tests_properties("view: ${stage} ${names} (one process)" PROPERTIES FIXTURES_SETUP views)
    endif()
endforeach()
# The thumbnail strip over the final frame (the window's T key; --thumbnails headless).
add_test(NAME "view: tutorial10_part3_gaussian thumbnails"
         COMMAND ${BIN}/tutorial10_part3_gaussian ${VIEW_ARGS} --size 640x360 --thumbnails
                 --output ${VIEWS}/tutorial10_part3_gaussian/thumbnails/frame.png --dump ${VIEWS}/tutorial10_part3_gaussian/thumbnails)
set_tests_properties("view: tutorial10_part3_gaussian thumbnails" PROPERTIES FIXTURES_SETUP views)
add_test(NAME "view: an unknown view name is bad usage"
         COMMAND ${EXPECT} 2 "--view glow: unknown view \\(choose from final, hdr, luminance" --
                 ${BIN}/tutorial10_part0_start ${VIEW_ARGS} --view glow)

# The nan view on the synthetic inputs with one non-finite texel (make_test_images): the caption's
# counts are kept for the checks, with the HDR buffer as read back (--exr) in case loading ever
# clamps non-finite input.
# t10_add_nan_view(<name> <stage> <input> [<root> <shader dir> <fixture>]): the last three render a
# mutant shader into another folder.
function(t10_add_nan_view name stage input)
    set(root ${VIEWS})
    set(extra "")
    set(fixture views)
    set(label "")
    if(ARGC GREATER 3)
        set(label " (mutant)")
        set(root ${ARGV3})
        set(extra "--shader-dir ${ARGV4}")
        set(fixture ${ARGV5})
    endif()
    set(dir ${root}/nan_${name})
    # The input sets the size (64x64); --keep-non-finite: the view is what must show the NaN and inf.
    add_test(NAME "view: nan ${name}${label}"
             COMMAND sh -c "mkdir -p ${dir} && ${BIN}/${stage} --headless --backend egl --frames 1 --view nan ${extra} \
                            --keep-non-finite --input ${DUMPS}/inputs/${input} --output ${dir}/frame.png --exr ${dir}/hdr.exr \
                            --dump ${dir} > ${dir}/stdout.txt")
    set_tests_properties("view: nan ${name}${label}" PROPERTIES FIXTURES_SETUP ${fixture} FIXTURES_REQUIRED inputs)
endfunction()
t10_add_nan_view(part1_nan tutorial10_part1_tonemap nan.exr)
t10_add_nan_view(part1_inf tutorial10_part1_tonemap inf.exr)
t10_add_nan_view(part3_inf tutorial10_part3_gaussian inf.exr)

add_executable(t10_views_tests views/test_views.cpp)
target_link_libraries(t10_views_tests PRIVATE t10_reference t10_flags t10_catch)
catch_discover_tests(t10_views_tests TEST_PREFIX "views: "
                     PROPERTIES FIXTURES_REQUIRED views ENVIRONMENT T10_DUMP_DIR=${VIEWS})

# The checks can fail: View.frag with one thing changed, rendered through --shader-dir, must fail
# the check that guards it.
# t10_add_view_mutant(<name> <stage> <view> <from> <to> <test case> <failing check regex>)
function(t10_add_view_mutant name stage view from to testcase check)
    file(READ ${PROJECT_SOURCE_DIR}/common/shaders/views/View.frag source)
    string(FIND "${source}" "${from}" found)
    if(found EQUAL -1)
        message(FATAL_ERROR "view mutant ${name}: '${from}' not found in View.frag")
    endif()
    string(REPLACE "${from}" "${to}" mutated "${source}")
    set(root ${VIEWS}/mutants/${name})
    file(WRITE ${root}/shaders/views/View.frag "${mutated}")
    add_test(NAME "view: mutant ${name}"
             COMMAND ${BIN}/${stage} ${VIEW_ARGS} --view ${view} --shader-dir ${root}/shaders
                     --output ${root}/${stage}/${view}/frame.png --dump ${root}/${stage}/${view})
    set_tests_properties("view: mutant ${name}" PROPERTIES FIXTURES_SETUP view_mutants)
    add_test(NAME "views reject: ${name}"
             COMMAND ${EXPECT} nonzero "${check}" -- ${CMAKE_COMMAND} -E env T10_DUMP_DIR=${root}
                     ${BIN}/t10_views_tests "${testcase}")
    set_tests_properties("views reject: ${name}" PROPERTIES FIXTURES_REQUIRED view_mutants)
endfunction()
t10_add_view_mutant(luminance_scaled tutorial10_part1_tonemap luminance
                    "float fT = iMapped == 1 ? fValue :" "float fT = iMapped == 1 ? fValue * 0.97 :"
                    "luminance view decodes to the CPU log luminance (part1)" "CHECK\\( worst <= kDecodeTolerance \\)")
t10_add_view_mutant(bloom1_shows_level0 tutorial10_part3_gaussian bloom1
                    "display(fetch(s2Bloom1).rgb)" "display(fetch(s2Bloom0).rgb)"
                    "bloom1 view shows the read-back level 1 (part3)" "CHECK\\( error.max <= 1 \\)")
t10_add_view_mutant(ev_stop_off_by_one tutorial10_part1_tonemap ev
                    "int(floor(log2(fY / fKey)))" "int(floor(log2(fY / fKey))) + 1"
                    "ev view matches the CPU classification of the HDR buffer (part1)"
                    "CHECK\\( mismatched <= allowed \\)")
t10_add_view_mutant(key_marker_shifted tutorial10_part1_tonemap key
                    "int iMarker = clamp(int(fKeyPosition * float(i2Size.x))"
                    "int iMarker = clamp(int(fKeyPosition * float(i2Size.x)) + 8"
                    "key view is a flat swatch of the smallest luminance level with the key marked on a scale strip (part1)"
                    "CHECK\\( std::abs\\(marked.front\\(\\) - expectedColumn\\) <= 1 \\)")
# The nan view's marking: a View.frag that never marks the accumulation must fail.
file(READ ${PROJECT_SOURCE_DIR}/common/shaders/views/View.frag source)
string(REPLACE "bool bBad = nonFinite(v4Colour);" "bool bBad = false;" mutated "${source}")
if(mutated STREQUAL source)
    message(FATAL_ERROR "view mutant nan_unmarked: the marking line is not in View.frag")
endif()
file(WRITE ${VIEWS}/mutants/nan_unmarked/shaders/views/View.frag "${mutated}")
t10_add_nan_view(part1_nan tutorial10_part1_tonemap nan.exr ${VIEWS}/mutants/nan_unmarked
                 ${VIEWS}/mutants/nan_unmarked/shaders view_mutants)
add_test(NAME "views reject: nan_unmarked"
         COMMAND ${EXPECT} nonzero "CHECK\\( missed == 0 \\)" -- ${CMAKE_COMMAND} -E env
                 T10_DUMP_DIR=${VIEWS}/mutants/nan_unmarked ${BIN}/t10_views_tests
                 "nan view counts and marks the non-finite texels (part1 NaN input)")
set_tests_properties("views reject: nan_unmarked" PROPERTIES FIXTURES_REQUIRED "view_mutants;inputs")

# The thumbnails' check: a View.frag that samples each thumbnail with the framebuffer's size instead
# of the slot's must fail it.
file(READ ${PROJECT_SOURCE_DIR}/common/shaders/views/View.frag source)
string(REPLACE "(ivec2(gl_FragCoord.xy) - i2Origin) * i2TexSize / i2Size" "ivec2(gl_FragCoord.xy) - i2Origin" mutated "${source}")
if(mutated STREQUAL source)
    message(FATAL_ERROR "view mutant thumbnail_unscaled: the texel line is not in View.frag")
endif()
set(root ${VIEWS}/mutants/thumbnail_unscaled)
file(WRITE ${root}/shaders/views/View.frag "${mutated}")
add_test(NAME "view: mutant thumbnail_unscaled"
         COMMAND ${BIN}/tutorial10_part3_gaussian ${VIEW_ARGS} --size 640x360 --thumbnails --shader-dir ${root}/shaders
                 --output ${root}/tutorial10_part3_gaussian/thumbnails/frame.png --dump ${root}/tutorial10_part3_gaussian/thumbnails)
set_tests_properties("view: mutant thumbnail_unscaled" PROPERTIES FIXTURES_SETUP view_mutants)
add_test(NAME "views reject: thumbnail_unscaled"
         COMMAND ${EXPECT} nonzero "CHECK\\( worst <= 1 \\)" -- ${CMAKE_COMMAND} -E env T10_DUMP_DIR=${root}
                 ${BIN}/t10_views_tests "thumbnails show the accumulation and a label under the frame (part3)")
set_tests_properties("views reject: thumbnail_unscaled" PROPERTIES FIXTURES_REQUIRED view_mutants)

# The window path: the view is drawn after the stage's frame (and, in extras, under the panel).
if(XVFB_RUN)
    foreach(stage tutorial10_part3_gaussian extras)
        add_test(NAME "view: ${stage} ev in a window"
                 COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${EXPECT} 0 "^view ev: " --
                         ${BIN}/${stage} --backend window --size 640x360 --frames 3 --view ev --thumbnails
                         --output ${VIEWS}/window/${stage}_ev.png)
    endforeach()
endif()
