# t10_add_stage(<folder>): one program per stage folder. The folder holds Tutorial10.cpp and the
# stage's shaders; the shaders are found at run time through T10_STAGE_SHADER_DIR (fixed here, at
# configure time) and common/shaders, never relative to the working directory.
function(t10_add_stage folder)
    add_executable(${folder} ${PROJECT_SOURCE_DIR}/${folder}/Tutorial10.cpp)
    target_link_libraries(${folder} PRIVATE t10_common t10_flags)
    target_compile_definitions(${folder} PRIVATE
        T10_STAGE_NAME="${folder}"
        T10_STAGE_SHADER_DIR="${PROJECT_SOURCE_DIR}/${folder}")
    set_property(GLOBAL APPEND PROPERTY T10_STAGES ${folder})
endfunction()
