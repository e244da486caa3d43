#!/usr/bin/env bash
# Builds the Windows prefix `make windows-check` compiles against, with Debian's MinGW-w64:
#   - GLFW, Imath, OpenEXR, Catch2 and Dear ImGui from Debian's own source packages (apt-get source),
#     compiled as static libraries;
#   - the header-only libraries (glm, CLI11, nlohmann-json, stb, tinygltf) copied from the installed
#     Debian packages' headers, with their CMake packages where Debian has one; stb flat in include/
#     and tinygltf without a CMake package, as vcpkg installs them (cmake/T10HeaderOnly.cmake finds
#     both that way).
# Each library is built once; a stamp file holding the source version marks it done, so a second run
# takes seconds. zlib is Debian's libz-mingw-w64-dev.
# usage: build_deps.sh DEPS_DIR (the prefix is DEPS_DIR/prefix)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
deps=$(mkdir -p "$1" && cd "$1" && pwd)
prefix=$deps/prefix
toolchain=$root/cmake/toolchains/mingw-w64-x86_64.cmake
jobs=${JOBS:-2}
mkdir -p "$prefix/include" "$prefix/share/cmake" "$deps/stamps"

"$here/fetch_sources.sh" "$deps" glfw3 imath openexr catch2 imgui

# build_one NAME CMAKE_ARGS...: configure, build and install src/NAME-*/ into the prefix (with
# CMAKE_SOURCE set: that CMake project instead, given the unpacked source as IMGUI_SOURCE_DIR).
build_one() {
    local name=$1
    shift
    local source
    source=$(ls -d "$deps/src/$name"-*/ | head -n 1)
    local project=${CMAKE_SOURCE:-$source}
    local stamp=$deps/stamps/$name
    if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$source" ]; then return; fi
    echo "windows-deps: building $(basename "$source")"
    rm -rf "$deps/build/$name"
    cmake -S "$project" -B "$deps/build/$name" -G Ninja --toolchain "$toolchain" -Wno-dev \
        -DT10_WINDOWS_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
        -DBUILD_SHARED_LIBS=OFF -DBUILD_TESTING=OFF "$@" >"$deps/build-$name.log" 2>&1 &&
    cmake --build "$deps/build/$name" -j "$jobs" >>"$deps/build-$name.log" 2>&1 &&
    cmake --install "$deps/build/$name" >>"$deps/build-$name.log" 2>&1 || {
        tail -n 30 "$deps/build-$name.log"
        echo "windows-deps: $name failed to build (whole log: $deps/build-$name.log)"
        exit 1
    }
    echo "$source" >"$stamp"
}

build_one glfw3 -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF -DGLFW_BUILD_DOCS=OFF
build_one imath -DPYTHON=OFF
build_one openexr -DOPENEXR_BUILD_TOOLS=OFF -DOPENEXR_INSTALL_TOOLS=OFF -DOPENEXR_INSTALL_EXAMPLES=OFF \
    -DOPENEXR_INSTALL_PKG_CONFIG=OFF -DDOCS=OFF
build_one catch2 -DCATCH_BUILD_TESTING=OFF -DCATCH_INSTALL_DOCS=OFF -DCATCH_BUILD_STATIC_LIBRARY=ON
# Dear ImGui (extras/): Debian's source has no build system for the backends; ours is in imgui/.
CMAKE_SOURCE=$here/imgui build_one imgui -DIMGUI_SOURCE_DIR="$(ls -d "$deps"/src/imgui-*/ | head -n 1)"

# Header-only libraries from the Debian packages installed on this machine (make deps), copied with
# their timestamps (-p): a fresh copy of unchanged headers must not make the next build recompile all.
for dir in glm CLI nlohmann; do
    rm -rf "${prefix:?}/include/$dir"
    cp -rp "/usr/include/$dir" "$prefix/include/$dir"
done
for package in glm CLI11 nlohmann_json; do
    rm -rf "${prefix:?}/share/cmake/$package"
    cp -rp "/usr/share/cmake/$package" "$prefix/share/cmake/$package"
done
cp -p /usr/include/stb/stb_image.h /usr/include/stb/stb_image_write.h "$prefix/include/"
cp -p /usr/include/tiny_gltf.h "$prefix/include/"
echo "windows-deps: prefix ready in $prefix"
