# The compare page of a student's web build (`make web STAGE=student_partN`, then
# out/web/student_partN/index.html?compare=1): the student's frame beside the reference part's, the
# difference heat-map and the golden test's verdict with its tolerance.
#
# t10_web_compare(<target> <folder>), called for each student stage of the web build
# (cmake/T10Student.cmake):
#   - which part the folder is: its name (partN, as `make student PART=N` names it), else its
#     Tutorial10.cpp's header line "Tutorial 10, Part N" (make student writes it); the reference is
#     then the Nth of T10_GOLDEN_STAGES, and its tests/golden/<reference>.tolerance is packaged at
#     /t10/compare/reference.tolerance;
#   - the golden comparison itself (t10_compare_export: common/base compare.cpp behind the C functions of common/platform/web/compare_export.cpp)
#     linked in, so the page judges with the tests' code;
#   - common/platform/web/compare_page.js as --post-js (it acts only with ?compare=1) and a --pre-js
#     naming the reference (t10CompareReference);
#   - the reference stage's page built with it (a dependency), since the compare page loads it.
# A folder whose part cannot be told still builds; its compare page says why it has no reference.
function(t10_web_compare target folder)
    get_filename_component(name ${folder} NAME)
    set(part "")
    if(name MATCHES "(^|_)part([1-3])($|_)")
        set(part ${CMAKE_MATCH_2})
    elseif(EXISTS ${folder}/Tutorial10.cpp)
        file(STRINGS ${folder}/Tutorial10.cpp header LIMIT_COUNT 5 REGEX "Tutorial 10, Part [1-3]")
        if(header MATCHES "Tutorial 10, Part ([1-3])")
            set(part ${CMAKE_MATCH_1})
        endif()
    endif()
    set(reference "")
    if(part)
        list(GET T10_GOLDEN_STAGES ${part} reference)
    endif()
    set(config ${PROJECT_BINARY_DIR}/compare/${target}.pre.js)
    file(CONFIGURE OUTPUT ${config} CONTENT
         "// Written by cmake/T10WebCompare.cmake: the reference stage ${target}'s compare page loads.\nvar t10CompareReference = \"@reference@\";\n"
         @ONLY)
    target_link_libraries(${target} PRIVATE t10_compare_export)
    target_link_options(${target} PRIVATE
        "SHELL:--pre-js ${config}"
        "SHELL:--post-js ${PROJECT_SOURCE_DIR}/common/platform/web/compare_page.js")
    set(depends ${config} ${PROJECT_SOURCE_DIR}/common/platform/web/compare_page.js)
    if(reference)
        set(tolerance ${PROJECT_SOURCE_DIR}/tests/golden/${reference}.tolerance)
        target_link_options(${target} PRIVATE "SHELL:--preload-file ${tolerance}@/t10/compare/reference.tolerance")
        list(APPEND depends ${tolerance})
        # The page loads the reference's page beside it: `make web STAGE=student_partN` builds both.
        if(TARGET ${reference})
            add_dependencies(${target} ${reference})
        endif()
    else()
        message(WARNING "${folder}: the web compare page has no reference: name the folder partN (N = 1, 2, 3)")
    endif()
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${depends})
endfunction()

# t10_web_compare_test_students(): the two student stages the browser tests judge with their compare
# pages (tests/web/web_tests.cmake): copies of tutorial10_part1_tonemap/ made at configure time in
# <build>/compare-test-students/, one with a planted mistake (the tone map's white point Yw 1.0 instead
# of 0.22, step 9: a student's typo), one unchanged. They are built as students' folders are (not part
# of `all`); the target t10_web_compare_test_students builds both.
function(t10_web_compare_test_students)
    set(reference ${PROJECT_SOURCE_DIR}/tutorial10_part1_tonemap)
    set(root ${PROJECT_BINARY_DIR}/compare-test-students)
    set(files Tutorial10.cpp PostProcess.frag PostProcessInit.frag)
    set(targets "")
    foreach(kind fixed planted)
        set(folder ${root}/t10test_${kind}_part1)
        file(MAKE_DIRECTORY ${folder})
        foreach(file IN LISTS files)
            set(source ${reference}/${file})
            if(kind STREQUAL planted AND file STREQUAL PostProcess.frag)
                file(READ ${source} text)
                set(right "const float fYwhite = 0.22f;")
                string(FIND "${text}" "${right}" at)
                if(at EQUAL -1)
                    message(FATAL_ERROR "${source}: '${right}' not found: the compare test's planted mistake "
                                        "(cmake/T10WebCompare.cmake) needs another line")
                endif()
                string(REPLACE "${right}" "const float fYwhite = 1.0f;" text "${text}")
                set(source ${root}/planted-${file})
                file(WRITE ${source} "${text}")
            endif()
            # Copied only when changed, so that the stage is not relinked at every configure.
            file(COPY_FILE ${source} ${folder}/${file} ONLY_IF_DIFFERENT)
        endforeach()
        t10_add_student_stage(t10test_${kind}_part1 ${folder})
        # Test fixtures: -O1 (after the build type's -O3, so it wins) spares them wasm-opt's -O3 passes
        # at link in make test; what they test, the page and the comparison, does not depend on it.
        target_compile_options(student_t10test_${kind}_part1 PRIVATE -O1)
        target_link_options(student_t10test_${kind}_part1 PRIVATE -O1)
        list(APPEND targets student_t10test_${kind}_part1)
    endforeach()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${reference}/Tutorial10.cpp
                 ${reference}/PostProcess.frag ${reference}/PostProcessInit.frag)
    add_custom_target(t10_web_compare_test_students DEPENDS ${targets})
endfunction()
