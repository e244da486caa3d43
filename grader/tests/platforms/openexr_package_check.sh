#!/usr/bin/env bash
# Tests cmake/T10OpenEXR.cmake's choice between OpenEXR's two CMake packages without either release
# installed: small stand-in config packages play OpenEXR 3 (exports OpenEXR::OpenEXR), 2.5 (Ubuntu
# 22.04: exports OpenEXR::IlmImf only) and 2.3 (too old), and a project of no language includes the
# module with each. 3 and 2.5 configure, with OpenEXR::OpenEXR the package's own target or an alias of
# OpenEXR::IlmImf; 2.3 stops with a message naming the version and the package.
#   usage: openexr_package_check.sh CHECKOUT OUT
set -u
checkout=$(cd "$1" && pwd) out=$2
rm -rf "$out" && mkdir -p "$out/project" || exit 1
cat > "$out/project/CMakeLists.txt" <<EOF
cmake_minimum_required(VERSION 3.25)
project(openexr_check NONE)
include("$checkout/cmake/T10OpenEXR.cmake")
get_target_property(aliased OpenEXR::OpenEXR ALIASED_TARGET)
message(STATUS "check: OpenEXR::OpenEXR is \${aliased}")
EOF
# package VERSION TARGET: a config package of that version exporting TARGET, in $out/VERSION.
package() {
    mkdir -p "$out/$1"
    printf 'add_library(%s INTERFACE IMPORTED)\n' "$2" > "$out/$1/OpenEXRConfig.cmake"
    printf 'set(PACKAGE_VERSION %s)\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n' "$1" > "$out/$1/OpenEXRConfigVersion.cmake"
}
package 3.1.5 OpenEXR::OpenEXR
package 2.5.7 OpenEXR::IlmImf
package 2.3.0 OpenEXR::IlmImf

failures=0
# configure VERSION EXPECTED_EXIT WORDS: configures with the package of VERSION and looks for WORDS.
configure() {
    cmake -S "$out/project" -B "$out/build-$1" -DOpenEXR_DIR="$out/$1" > "$out/$1.log" 2>&1
    code=$?
    if [ "$code" != "$2" ] && { [ "$2" = 0 ] || [ "$code" = 0 ]; }; then
        echo "FAIL OpenEXR $1: cmake exit $code, expected $2"; cat "$out/$1.log"; failures=$((failures + 1)); return
    fi
    grep -qF -- "$3" "$out/$1.log" || { echo "FAIL OpenEXR $1: no '$3' in:"; cat "$out/$1.log"; failures=$((failures + 1)); }
}
configure 3.1.5 0 "check: OpenEXR::OpenEXR is aliased-NOTFOUND"
configure 2.5.7 0 "check: OpenEXR::OpenEXR is OpenEXR::IlmImf"
configure 2.3.0 1 "OpenEXR 2.3.0 is too old: 2.5 or 3 is needed (Debian: libopenexr-dev)"

[ $failures = 0 ] && echo "cmake/T10OpenEXR.cmake: OpenEXR 3's target used, 2.5's aliased, 2.3 refused"
exit $(( failures > 0 ))
