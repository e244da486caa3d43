#!/usr/bin/env bash
# `make windows-check`: proves the project builds and renders on Windows without a Windows machine.
#   1. the Windows prefix (build_deps.sh: GLFW, Imath, OpenEXR, Catch2 from Debian's source packages;
#      the header-only libraries from Debian's headers), built once and cached;
#   2. the whole project cross-compiled with MinGW-w64 (cmake/toolchains/mingw-w64-x86_64.cmake),
#      warnings as errors, into BUILD_DIR;
#   3. its Windows tests (tests/windows_tests.cmake) run by ctest under Wine in Xvfb: the four stages'
#      golden comparisons through the WGL pbuffer backend (Wine hands WGL to the host's Mesa), the
#      proof that each golden rejects an altered image, the Catch2 unit and GL tests.
# Prints each result and the time of each step; exits non-zero when anything fails. A host whose
# Debian archive cannot give the libraries' source packages gets "SKIPPED: <reason>" and exit 0.
# usage: windows_check.sh DEPS_DIR BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
deps=$1
build=$2
jobs=${JOBS:-2}
start=$(date +%s)
step() { echo "windows-check: $* ($(($(date +%s) - start)) s)"; }

for tool in x86_64-w64-mingw32-g++-posix wine wineserver xvfb-run; do
    command -v "$tool" >/dev/null || { echo "windows-check: $tool not found (make windows-check installs it)"; exit 1; }
done

step "Windows libraries into $deps/prefix"
rc=0
"$here/build_deps.sh" "$deps" || rc=$?
if [ "$rc" -eq 77 ]; then
    # fetch_sources.sh could not get a library's source from this host's archive: nothing was built,
    # so nothing is proven either way; say so instead of passing or blaming the code.
    echo "SKIPPED: make windows-check: this host's Debian archive does not give every source package the Windows prefix is built from"
    exit 0
fi
[ "$rc" -eq 0 ] || exit "$rc"
prefix=$(cd "$deps/prefix" && pwd)

# Two students' folders, as a Windows student makes them (README, "Windows"): part1 holds Part 1's
# reference and must pass Part 1's golden; part2 holds Part 1's code too and must fail Part 2's.
students=$build-students
for part in 1 2; do
    mkdir -p "$students/part$part"
    cp -p "$root"/tutorial10_part1_tonemap/* "$students/part$part/"  # -p: an unchanged copy rebuilds nothing
done

step "cross-compiling the project into $build"
if [ ! -f "$build/build.ninja" ]; then
    cmake -S "$root" -B "$build" -G Ninja --toolchain "$root/cmake/toolchains/mingw-w64-x86_64.cmake" \
        -DT10_WINDOWS_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Debug \
        -DT10_STUDENT_DIR="$(cd "$students" && pwd)" >"$build.configure.log" 2>&1 || {
        cat "$build.configure.log"; echo "windows-check: the Windows configuration failed"; exit 1; }
fi
cmake --build "$build" -j "$jobs" --target all student_part1 student_part2 >"$build.build.log" 2>&1 || {
    grep -v '^\[[0-9]*/[0-9]*\] ' "$build.build.log" | head -n 60
    echo "windows-check: the Windows build failed (whole log: $build.build.log)"
    exit 1
}

# A Wine prefix of our own under the build folder (created once, about 20 s), quiet Wine.
export WINEPREFIX
WINEPREFIX=$(cd "$build" && pwd)/wineprefix
export WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
if [ ! -f "$WINEPREFIX/system.reg" ]; then
    step "creating the Wine prefix $WINEPREFIX"
    wine wineboot --init >/dev/null 2>&1
    wineserver -w
fi

step "running the Windows tests under Wine (xvfb-run)"
# The screen is smaller than some frames on purpose: the headless backend must not be clamped to it.
set +e
(cd "$build" && xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j "$jobs" -E student_part2) |
    tee "$build.ctest.log"
status=${PIPESTATUS[0]}
# What the Catch2 programs said (ctest counts each program once).
cp "$build/Testing/Temporary/LastTest.log" "$build.ctest-full.log"
for program in unit gl; do
    summary=$(sed -n "/ Test: $program: all\$/,/^Test Passed\|^Test Failed/p" "$build.ctest-full.log" |
              grep -E '^(All tests passed|test cases:)' | tail -n 1 || true)
    echo "windows-check: $program tests: ${summary:-no summary (see $build.ctest-full.log)}"
done
# The student check can fail: Part 1's code as part 2 must not pass Part 2's golden.
(cd "$build" && xvfb-run -a -s "-screen 0 1280x1024x24" ctest -R student_part2) >"$build.ctest-reject.log" 2>&1
if [ $? -eq 0 ]; then
    echo "windows-check: FAILED: Part 1's code passed Part 2's golden as student_part2 (the student check cannot fail)"
    status=1
else
    echo "windows-check: student_part2 (Part 1's code) rejected by Part 2's golden, as it must be"
fi
set -e
wineserver -k 2>/dev/null || true
step "done, ctest exit status $status"
exit "$status"
