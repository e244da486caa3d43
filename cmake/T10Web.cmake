# The browser build (`make web`, or `emcmake cmake --preset web` with any emscripten): every stage
# compiled to WebAssembly + WebGL 2 from the same Tutorial10.cpp and shaders, into
# T10_WEB_OUTPUT_DIR/<stage>/ (index.html, <stage>.js, .wasm, .data). Included from the top-level
# CMakeLists.txt instead of the desktop packages when the toolchain is emscripten's.
#
# What the desktop build finds as packages comes from elsewhere here:
#   GLFW      emscripten's own (-sUSE_GLFW=3: the GLFW 3.2 API, in JavaScript)
#   GL        OpenGL ES 3.0 (WebGL 2) through common/platform/web/include/glad/gl.h
#   glm, CLI11, nlohmann-json, stb, tinygltf  the same header-only libraries as the desktop build
#             (Debian: libglm-dev libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev, or
#             Homebrew's), found outside emscripten's sysroot and linked into the build tree one
#             by one, so that no other host header reaches the WebAssembly compiler; stb's and
#             tinygltf's code is compiled here (cmake/T10HeaderOnly.cmake)
#   OpenEXR   none: it has no WebAssembly build; --exr and --input say so (image_io.cpp)
# Version notes (emscripten 3.1.6 on Debian 12, 3.1.69 on Debian 13): exceptions are off by default
# in both (-fexceptions at compile and link); every WebGL extension our context enables is enabled
# by name (context_web.cpp), since 3.1.6 enables all and later versions a list; the page is our own
# (common/platform/web/index.html.in), not emcc's HTML output, whose minifier crashes in 3.1.6 at -O1
# and above; explicit uniform locations are mapped by the platform (gl_web.cpp), not by
# -sGL_EXPLICIT_UNIFORM_LOCATION, which in 3.1.6 drops a glUniform* made before any
# glGetUniformLocation.
set(T10_WEB_OUTPUT_DIR ${PROJECT_BINARY_DIR}/web CACHE PATH "Where each web stage's folder is written")
set(T10_BUILD_TESTS OFF CACHE BOOL "" FORCE) # the tests run natively (make test) and drive the pages

# The web preset turns warnings-as-errors off (warnings still print): the same sources are held to
# -Werror by the native builds (g++ 12 and 14, MinGW), while emscripten's clang changes with every
# release (clang 15-era in 3.1.6, clang 19 in Debian 13's 3.1.69) and a student's own emscripten may be
# any version: a warning new to it should not keep a page from building.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# The unity build (the top-level CMakeLists.txt turns it on for every build) took the web build from
# about 270 to about 170 CPU-seconds (-O1, all five pages).

# The host's header-only libraries, each linked into host-include/ by name.
set(T10_WEB_HOST_PREFIXES /usr/include /usr/local/include /opt/homebrew/include
    CACHE STRING "Folders searched for glm, CLI11, nlohmann-json, stb and tinygltf's headers")
set(t10_web_include ${PROJECT_BINARY_DIR}/host-include)
file(MAKE_DIRECTORY ${t10_web_include})
function(t10_web_host_header variable probe link_name)
    find_path(${variable} ${probe} PATHS ${T10_WEB_HOST_PREFIXES} PATH_SUFFIXES stb NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
    if(NOT ${variable})
        message(FATAL_ERROR "web build: ${probe} not found in ${T10_WEB_HOST_PREFIXES} (Debian: libglm-dev "
                            "libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev; set T10_WEB_HOST_PREFIXES)")
    endif()
    if(NOT EXISTS ${t10_web_include}/${link_name})
        file(CREATE_LINK ${${variable}}/${link_name} ${t10_web_include}/${link_name} SYMBOLIC COPY_ON_ERROR)
    endif()
endfunction()
t10_web_host_header(T10_WEB_GLM_DIR glm/glm.hpp glm)
t10_web_host_header(T10_WEB_CLI11_DIR CLI/CLI.hpp CLI)
t10_web_host_header(T10_WEB_JSON_DIR nlohmann/json.hpp nlohmann)
t10_web_host_header(T10_WEB_TINYGLTF_DIR tiny_gltf.h tiny_gltf.h)
foreach(header stb_image.h stb_image_write.h)
    t10_web_host_header(T10_WEB_STB_DIR_${header} ${header} ${header})
endforeach()

# Dear ImGui's headers, for extras' panel code, which the browser build compiles but never calls
# (common/CMakeLists.txt, t10_panel).
add_library(t10_web_imgui_headers INTERFACE)
find_path(T10_WEB_IMGUI_DIR imgui.h PATHS ${T10_WEB_HOST_PREFIXES} PATH_SUFFIXES imgui NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
if(T10_WEB_IMGUI_DIR)
    foreach(header imgui.h imconfig.h)
        if(NOT EXISTS ${t10_web_include}/imgui/${header})
            file(MAKE_DIRECTORY ${t10_web_include}/imgui)
            file(CREATE_LINK ${T10_WEB_IMGUI_DIR}/${header} ${t10_web_include}/imgui/${header} SYMBOLIC COPY_ON_ERROR)
        endif()
    endforeach()
    target_include_directories(t10_web_imgui_headers SYSTEM INTERFACE ${t10_web_include}/imgui)
elseif(T10_BUILD_EXTRAS)
    message(FATAL_ERROR "web build: Dear ImGui's imgui.h not found in ${T10_WEB_HOST_PREFIXES} (Debian: libimgui-dev), "
                        "which extras/ includes; or configure with -DT10_BUILD_EXTRAS=OFF")
endif()

add_library(t10_web_headers INTERFACE)
target_include_directories(t10_web_headers SYSTEM INTERFACE ${t10_web_include})
foreach(name glm::glm CLI11::CLI11 nlohmann_json::nlohmann_json)
    add_library(${name} ALIAS t10_web_headers)
endforeach()
set(T10_STB_INCLUDE_DIR ${t10_web_include} CACHE PATH "" FORCE)
set(T10_TINYGLTF_INCLUDE_DIR ${t10_web_include} CACHE PATH "" FORCE)
include(cmake/T10HeaderOnly.cmake)

# GLFW: emscripten's; GL: the ES 3.0 header standing in for glad's desktop loader.
add_library(glfw INTERFACE)
target_link_options(glfw INTERFACE -sUSE_GLFW=3)
add_library(glad INTERFACE)
target_include_directories(glad SYSTEM INTERFACE ${PROJECT_SOURCE_DIR}/common/platform/web/include)
target_link_options(glad INTERFACE -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)

# Where the stages' files lie in the page's virtual file system (--preload-file), the same paths
# T10_COMMON_SHADER_DIR, T10_ASSET_DIR and T10_STAGE_SHADER_DIR name in the desktop build.
set(T10_WEB_ROOT /t10)
set(T10_COMMON_SHADER_DIR_VALUE ${T10_WEB_ROOT}/common/shaders)
set(T10_ASSET_DIR_VALUE ${T10_WEB_ROOT}/common/assets)

# The page's check (Module.t10Check): t10-grade's checks compiled for every page (grader/page/page.cmake).
include(${PROJECT_SOURCE_DIR}/grader/page/page.cmake)

# t10_web_stage(<target> <shader folder>): links a stage for the browser into
# T10_WEB_OUTPUT_DIR/<target>/ with its page and its files (its shaders, common/shaders, the scene).
function(t10_web_stage target folder)
    set(out ${T10_WEB_OUTPUT_DIR}/${target})
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${out} SUFFIX .js)
    target_link_options(${target} PRIVATE
        -sALLOW_MEMORY_GROWTH=1
        "SHELL:-sEXPORTED_RUNTIME_METHODS=['ccall','cwrap','UTF8ToString']"
        "SHELL:--exclude-file *.cpp --exclude-file *.md --exclude-file *.txt"
        "SHELL:--preload-file ${folder}@${T10_WEB_ROOT}/${target}"
        "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/common/shaders@${T10_COMMON_SHADER_DIR_VALUE}"
        "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/common/assets@${T10_ASSET_DIR_VALUE}"
        # The page's shader editing and check (Module.t10Shaders, t10SetShader, t10Check): workbench.js, the
        # grader's checks (t10_web_check) and their catalogue and rubric.
        "SHELL:--post-js ${PROJECT_SOURCE_DIR}/common/platform/web/workbench.js")
    target_link_libraries(${target} PRIVATE t10_web_check)
    foreach(file ${T10_WEB_GRADE_FILES})
        target_link_options(${target} PRIVATE "SHELL:--preload-file ${file}")
    endforeach()
    # Relinked when a packaged file changes. A glob, where the project lists files: what is packaged is
    # whole folders (a student's folder too), and the list only decides when to relink.
    file(GLOB_RECURSE packaged CONFIGURE_DEPENDS ${folder}/*.vert ${folder}/*.frag ${PROJECT_SOURCE_DIR}/common/shaders/*
         ${PROJECT_SOURCE_DIR}/common/assets/*)
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${packaged} ${PROJECT_SOURCE_DIR}/common/platform/web/workbench.js
                 ${PROJECT_SOURCE_DIR}/grader/diagnosis/mistakes.tsv ${PROJECT_SOURCE_DIR}/grader/scoring/rubric.txt)
    set(T10_WEB_STAGE ${target})
    # The page is made at configure time in the build folder and copied into the output folder by a
    # build rule, so that `make web` puts it back when the output is gone (rm -rf out: it did not).
    set(page ${CMAKE_CURRENT_BINARY_DIR}/pages/${target}/index.html)
    configure_file(${PROJECT_SOURCE_DIR}/common/platform/web/index.html.in ${page} @ONLY)
    add_custom_command(OUTPUT ${out}/index.html COMMAND ${CMAKE_COMMAND} -E copy ${page} ${out}/index.html
                       DEPENDS ${page} VERBATIM)
    add_custom_target(${target}_page DEPENDS ${out}/index.html)
    add_dependencies(${target} ${target}_page)
    t10_web_editor(${target} ${out})
endfunction()

# The shader editor of the pages (issue 52: the stage page with ?edit=1, and the site's embeds, which
# copy the same files through tools/build_site): CodeMirror 5 from Debian's libjs-codemirror, and the
# editor's own files (common/platform/web/editor.js and .css), copied into T10_WEB_OUTPUT_DIR/editor/ by
# build rules (as the pages are: `make web` puts them back when the output is gone), shared by every
# stage's page. Without CodeMirror the pages still build; their editor says which package is missing.
set(T10_CODEMIRROR_DIR /usr/share/javascript/codemirror CACHE PATH "CodeMirror 5 (Debian: libjs-codemirror)")
set(t10_web_editor_outputs "")
foreach(file common/platform/web/editor.js common/platform/web/editor.css)
    get_filename_component(name ${file} NAME)
    list(APPEND t10_web_editor_outputs ${T10_WEB_OUTPUT_DIR}/editor/${name})
    add_custom_command(OUTPUT ${T10_WEB_OUTPUT_DIR}/editor/${name}
                       COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/${file} ${T10_WEB_OUTPUT_DIR}/editor/${name}
                       DEPENDS ${PROJECT_SOURCE_DIR}/${file} VERBATIM)
endforeach()
foreach(file lib/codemirror.js lib/codemirror.css mode/clike/clike.js)
    if(NOT EXISTS ${T10_CODEMIRROR_DIR}/${file})
        message(WARNING "web build: ${T10_CODEMIRROR_DIR}/${file} not found, so the pages' shader editor "
                        "will say it is missing (Debian: libjs-codemirror; or set T10_CODEMIRROR_DIR)")
        break()
    endif()
    get_filename_component(name ${file} NAME)
    list(APPEND t10_web_editor_outputs ${T10_WEB_OUTPUT_DIR}/editor/codemirror/${name})
    add_custom_command(OUTPUT ${T10_WEB_OUTPUT_DIR}/editor/codemirror/${name}
                       COMMAND ${CMAKE_COMMAND} -E copy ${T10_CODEMIRROR_DIR}/${file} ${T10_WEB_OUTPUT_DIR}/editor/codemirror/${name}
                       DEPENDS ${T10_CODEMIRROR_DIR}/${file} VERBATIM)
endforeach()
add_custom_target(t10_web_editor_files DEPENDS ${t10_web_editor_outputs})

# t10_web_editor(<target> <out>): where the stage's editor starts, as `make student` starts a part: the
# shaders of the stage before it in T10_STAGES (Part 0's for Part 1, ...), copied into <out>/start/
# and listed in <out>/edit.json with the stage's part ("part1": the folder student/part1/ the editor's
# download is named after). A stage with none before it (Part 0, a student's own folder) starts from
# its own shaders. edit.json is written at configure time into the build folder and, like the start
# files, copied by build rules.
function(t10_web_editor target out)
    list(FIND T10_STAGES ${target} index)
    set(start "")
    if(index GREATER 0)
        math(EXPR previous "${index} - 1")
        list(GET T10_STAGES ${previous} start)
    endif()
    set(part ${target})
    if(target MATCHES "(^|_)(part[0-9])($|_)")
        set(part ${CMAKE_MATCH_2})
    endif()
    set(files "")
    set(outputs ${out}/edit.json)
    if(start)
        file(GLOB shaders CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${start}/*.vert ${PROJECT_SOURCE_DIR}/${start}/*.frag)
        foreach(shader IN LISTS shaders)
            get_filename_component(name ${shader} NAME)
            add_custom_command(OUTPUT ${out}/start/${name} COMMAND ${CMAKE_COMMAND} -E copy ${shader} ${out}/start/${name}
                               DEPENDS ${shader} VERBATIM)
            list(APPEND outputs ${out}/start/${name})
            list(APPEND files "\"${name}\"")
        endforeach()
        list(JOIN files ", " files)
        set(start "\"${start}\"")
    else()
        set(start null)
    endif()
    set(plan ${CMAKE_CURRENT_BINARY_DIR}/pages/${target}/edit.json)
    file(CONFIGURE OUTPUT ${plan}
         CONTENT "{\"stage\": \"${target}\", \"part\": \"${part}\", \"start\": ${start}, \"files\": [${files}]}\n")
    add_custom_command(OUTPUT ${out}/edit.json COMMAND ${CMAKE_COMMAND} -E copy ${plan} ${out}/edit.json DEPENDS ${plan} VERBATIM)
    add_custom_target(${target}_editor DEPENDS ${outputs})
    add_dependencies(${target} ${target}_editor t10_web_editor_files)
    target_link_options(${target} PRIVATE "SHELL:--post-js ${PROJECT_SOURCE_DIR}/common/platform/web/edit_page.js")
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${PROJECT_SOURCE_DIR}/common/platform/web/edit_page.js)
endfunction()
