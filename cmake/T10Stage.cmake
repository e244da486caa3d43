# t10_add_stage(<folder>): one program per stage folder, named after it. The folder holds
# Tutorial10.cpp and the stage's shaders; the shaders are found at run time through
# T10_STAGE_SHADER_DIR (fixed here, at configure time) and common/shaders, never relative to the
# working directory. The root CMakeLists.txt lists the stages; tests/CMakeLists.txt registers what
# each is checked against (t10_add_stage_tests).
function(t10_add_stage folder)
    add_executable(${folder} ${PROJECT_SOURCE_DIR}/${folder}/Tutorial10.cpp)
    target_link_libraries(${folder} PRIVATE t10_common t10_flags)
    if(EMSCRIPTEN)
        # The browser build: the folder's files are packaged at this path of the page's file system.
        target_compile_definitions(${folder} PRIVATE
            T10_STAGE_NAME="${folder}"
            T10_STAGE_SHADER_DIR="${T10_WEB_ROOT}/${folder}")
        t10_web_stage(${folder} ${PROJECT_SOURCE_DIR}/${folder})
        return()
    endif()
    target_compile_definitions(${folder} PRIVATE
        T10_STAGE_NAME="${folder}"
        T10_STAGE_SHADER_DIR="${PROJECT_SOURCE_DIR}/${folder}")
endfunction()
