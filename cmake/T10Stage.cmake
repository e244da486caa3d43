# t10_add_stage(<folder> [STEPS <first> <last>] [SAME_GOLDEN_AS <stage>]): one program per stage
# folder. STEPS names the tutorial steps the stage adds to the previous one (tests/stage_diff.py
# checks that its diff holds nothing else). The folder holds
# Tutorial10.cpp and the stage's shaders; the shaders are found at run time through
# T10_STAGE_SHADER_DIR (fixed here, at configure time) and common/shaders, never relative to the
# working directory. SAME_GOLDEN_AS marks a program whose default frame must equal another
# stage's golden (extras/ with default settings renders exactly Part 3).
function(t10_add_stage folder)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "SAME_GOLDEN_AS" "STEPS")
    add_executable(${folder} ${PROJECT_SOURCE_DIR}/${folder}/Tutorial10.cpp)
    target_link_libraries(${folder} PRIVATE t10_common t10_flags)
    target_compile_definitions(${folder} PRIVATE
        T10_STAGE_NAME="${folder}"
        T10_STAGE_SHADER_DIR="${PROJECT_SOURCE_DIR}/${folder}")
    set_property(GLOBAL APPEND PROPERTY T10_STAGES ${folder})
    if(ARG_STEPS)
        set_property(GLOBAL PROPERTY T10_STEPS_OF_${folder} ${ARG_STEPS})
    endif()
    if(ARG_SAME_GOLDEN_AS)
        set_property(GLOBAL PROPERTY T10_GOLDEN_OF_${folder} ${ARG_SAME_GOLDEN_AS})
    endif()
endfunction()
