# stb and tinygltf where they are headers only (vcpkg's ports, the MinGW prefix of `make
# windows-check`): no pkg-config module, no CMake package. Their headers are found with find_path and
# their implementations compiled once here, under the names Debian's packages give them
# (PkgConfig::STB, TinyGLTF::TinyGLTF), so that the targets linking them read the same everywhere.
# Included from the top-level CMakeLists.txt after the packages were looked for.
if(NOT TARGET PkgConfig::STB)
    find_path(T10_STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb)
    if(NOT T10_STB_INCLUDE_DIR)
        message(FATAL_ERROR "stb not found: neither pkg-config's stb (Debian: libstb-dev) nor stb_image.h "
                            "(vcpkg: stb) on the include path")
    endif()
    message(STATUS "stb: headers only in ${T10_STB_INCLUDE_DIR}; compiling stb_image and stb_image_write here")
    add_library(t10_stb STATIC ${CMAKE_CURRENT_LIST_DIR}/header_only/stb_impl.cpp)
    target_include_directories(t10_stb SYSTEM PUBLIC ${T10_STB_INCLUDE_DIR})
    add_library(PkgConfig::STB ALIAS t10_stb)
endif()
if(NOT TARGET TinyGLTF::TinyGLTF)
    find_path(T10_TINYGLTF_INCLUDE_DIR tiny_gltf.h)
    if(NOT T10_TINYGLTF_INCLUDE_DIR)
        message(FATAL_ERROR "tinygltf not found: neither its CMake package (Debian: libtinygltf-dev) nor "
                            "tiny_gltf.h (vcpkg: tinygltf) on the include path")
    endif()
    if(NOT TARGET nlohmann_json::nlohmann_json) # the browser build names its own (cmake/T10Web.cmake)
        find_package(nlohmann_json 3 REQUIRED)
    endif()
    message(STATUS "tinygltf: header only in ${T10_TINYGLTF_INCLUDE_DIR}; compiling it here")
    add_library(t10_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/header_only/tinygltf_impl.cpp)
    target_include_directories(t10_tinygltf SYSTEM PUBLIC ${T10_TINYGLTF_INCLUDE_DIR})
    target_link_libraries(t10_tinygltf PUBLIC PkgConfig::STB nlohmann_json::nlohmann_json)
    add_library(TinyGLTF::TinyGLTF ALIAS t10_tinygltf)
endif()
