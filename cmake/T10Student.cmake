# Students' own stages: every folder student/<name>/ holding a Tutorial10.cpp becomes the program
# build/bin/student_<name> (`make student PART=N` creates student/partN/). A student program is a
# stage in every way a user sees (t10_add_stage's definitions: its name, and its own folder as the
# shader folder, fixed at configure time, so --headless, --view, --scene and --bench all work), but:
#   - it is not part of `all` (EXCLUDE_FROM_ALL): a folder that does not build never breaks
#     `make build`, the reference stages or `make test`; `make check` and `make run STAGE=` build it
#     by name, so its compiler errors name the student's file and line;
#   - warnings stay warnings (t10_flags without -Werror): an unused variable does not stop the build;
#   - it is not in T10_STAGES, so no golden, view or stage-rule test is registered for it.
#
# T10_STUDENT_DIR (default: student/ in the source tree) may point elsewhere, which is how the tests
# build a scratch student folder without touching the source tree.
set(T10_STUDENT_DIR ${PROJECT_SOURCE_DIR}/student CACHE PATH "Folder whose sub-folders are students' own stages")

# t10_add_student_stage(<name> <folder>): the program student_<name> from <folder>/Tutorial10.cpp and
# the folder's shaders (t10_add_student_stages calls it for each folder; the web tests' compare
# stages, cmake/T10WebCompare.cmake, for theirs). In the web build the page gets the compare view too.
function(t10_add_student_stage name folder)
    # t10_flags without -Werror: the same warnings, definitions and (asan preset) sanitizers.
    if(NOT TARGET t10_student_flags)
        add_library(t10_student_flags INTERFACE)
        foreach(property COMPILE_OPTIONS COMPILE_DEFINITIONS LINK_OPTIONS SOURCES)
            get_target_property(values t10_flags INTERFACE_${property})
            if(values)
                list(REMOVE_ITEM values -Werror /WX)
                set_property(TARGET t10_student_flags PROPERTY INTERFACE_${property} ${values})
            endif()
        endforeach()
    endif()
    set(target student_${name})
    add_executable(${target} EXCLUDE_FROM_ALL ${folder}/Tutorial10.cpp)
    target_link_libraries(${target} PRIVATE t10_common t10_student_flags)
    if(EMSCRIPTEN)
        # The browser build (`make web STAGE=student_<name>`): the folder packaged with the page, and
        # ?compare=1 against the reference part (cmake/T10WebCompare.cmake).
        target_compile_definitions(${target} PRIVATE
            T10_STAGE_NAME="${target}"
            T10_STAGE_SHADER_DIR="${T10_WEB_ROOT}/${target}")
        t10_web_stage(${target} ${folder})
        t10_web_compare(${target} ${folder})
    else()
        target_compile_definitions(${target} PRIVATE
            T10_STAGE_NAME="${target}"
            T10_STAGE_SHADER_DIR="${folder}")
    endif()
endfunction()

# Why a glob here, where the project otherwise lists files explicitly: student/ is not part of the
# repository (it is ignored by git), so there is no list to keep; the glob only discovers folders, and
# CONFIGURE_DEPENDS makes the next build re-run it, so a folder created by `make student` is picked up
# without a manual re-configure. The files inside each folder are still named explicitly.
function(t10_add_student_stages)
    file(GLOB children LIST_DIRECTORIES true CONFIGURE_DEPENDS ${T10_STUDENT_DIR}/*)
    set(names "")
    set(lines "")
    foreach(child IN LISTS children)
        get_filename_component(name ${child} NAME)
        if(NOT IS_DIRECTORY ${child} OR NOT EXISTS ${child}/Tutorial10.cpp)
            continue()
        endif()
        # The folder name becomes a target and a file name: keep it to what both accept.
        if(NOT name MATCHES "^[A-Za-z0-9_]+$")
            message(WARNING "${child}: not built: a student folder's name may hold only letters, digits and _")
            continue()
        endif()
        t10_add_student_stage(${name} ${child})
        set(target student_${name})
        list(APPEND names ${target})
        string(APPEND lines "${target} ${child}\n")
    endforeach()
    # The Makefile reads this list, "<program> <folder>" per line (`make run STAGE=`, `make check`).
    file(WRITE ${PROJECT_BINARY_DIR}/student_stages.txt "${lines}")
    if(names)
        message(STATUS "Student stages in ${T10_STUDENT_DIR} (built by make check / make run STAGE=): ${names}")
    endif()
endfunction()
