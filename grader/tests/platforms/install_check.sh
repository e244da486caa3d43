#!/usr/bin/env bash
# Tests install_grader.sh's decisions without installing anything: apt-get, apt-cache, cmake, c++, id,
# python3 and make grader are stand-ins (on PATH before the system's) that play a release's packages
# and log what they are asked. Cases: Ubuntu 22.04's versions (a package missing, OpenEXR 2.5, CMake
# 3.22) stop before any install with one message naming them and the base image to choose; a release
# with every package but CMake 3.22 takes CMake from PyPI (pinned) and builds with it; Debian 12's
# CMake 3.25 builds with the system's; a user who is not root is refused.
#   usage: install_check.sh CHECKOUT OUT
set -u
checkout=$1 out=$2
script=$checkout/grader/platforms/install_grader.sh
rm -rf "$out" && mkdir -p "$out/bin" || exit 1
real_make=$(command -v make)
stub() { printf '#!/usr/bin/env bash\n%s\n' "$2" > "$out/bin/$1" && chmod +x "$out/bin/$1"; }
stub id '[ "$1" = -u ] && echo "${STUB_UID:-0}" || /usr/bin/id "$@"'
stub apt-get 'echo "apt-get $*" >> "$STUB_LOG"'
stub apt-cache 'case "$1" in
  show) for m in $STUB_MISSING; do [ "$m" = "${@: -1}" ] && exit 100; done; exit 0 ;;
  policy) [ "$2" = libopenexr-dev ] && echo "  Candidate: $STUB_EXR" ;;
esac'
stub cmake 'echo "cmake version $STUB_CMAKE"'
stub c++ 'echo "c++ (stand-in) 11.4.0"'
stub python3 'echo "python3 $*" >> "$STUB_LOG"; [ "$1 $2" = "-m venv" ] || exit 0
mkdir -p "$3/bin"
printf "#!/usr/bin/env bash\necho \"pip \$*\" >> \"\$STUB_LOG\"\n" > "$3/bin/pip"
printf "#!/usr/bin/env bash\necho \"cmake version 3.31.6\"\n" > "$3/bin/cmake"
chmod +x "$3/bin/pip" "$3/bin/cmake"'
stub make 'for a in "$@"; do [ "$a" = grader-packages ] && exec '"$real_make"' "$@"; done
echo "make $* with $(cmake --version)" >> "$STUB_LOG"'

failures=0
# run NAME EXPECTED_EXIT: runs the script with the STUB_* settings in the environment.
run() {
    log=$out/$1.log
    : > "$log"
    STUB_LOG=$log PATH=$out/bin:$PATH T10_CMAKE_VENV=$out/$1-venv bash "$script" "$checkout" > "$out/$1.out" 2>&1
    code=$?
    [ "$code" = "$2" ] || { echo "FAIL $1: exit $code, expected $2"; cat "$out/$1.out"; failures=$((failures + 1)); }
}
expect() { # expect CASE FILE(out|log) WORDS [absent]
    if grep -qF -- "$3" "$out/$1.$2"; then found=1; else found=0; fi
    if [ "${4:-}" = absent ]; then [ $found = 0 ] || { echo "FAIL $1: '$3' in its $2"; failures=$((failures + 1)); }
    else [ $found = 1 ] || { echo "FAIL $1: no '$3' in its $2:"; cat "$out/$1.$2"; failures=$((failures + 1)); }; fi
}

STUB_MISSING=libtinygltf-dev STUB_EXR=2.5.7-1ubuntu1 STUB_CMAKE=3.22.1 run jammy 1
expect jammy out "not in this release: libtinygltf-dev"
expect jammy out "too old: libopenexr-dev 2.5.7-1ubuntu1 (OpenEXR 3 is needed)"
expect jammy out "Ubuntu 24.04"
expect jammy log "install -y -qq --no-install-recommends cmake" absent
expect jammy log "make grader" absent

STUB_MISSING= STUB_EXR=3.1.5-5.1 STUB_CMAKE=3.22.1 run old-cmake 0
expect old-cmake out "CMake 3.22.1 is older than 3.25: installing CMake from PyPI"
expect old-cmake log "pip install --quiet --disable-pip-version-check cmake==3.31.6"
expect old-cmake log "make -C $checkout --no-print-directory grader"
expect old-cmake log "with cmake version 3.31.6"

STUB_MISSING= STUB_EXR=3.1.5-5 STUB_CMAKE=3.25.1 run bookworm 0
expect bookworm log "pip install" absent
expect bookworm log "with cmake version 3.25.1"
expect bookworm log "install -y -qq --no-install-recommends cmake ninja-build"

STUB_UID=1000 STUB_MISSING= STUB_EXR=3.1.5 STUB_CMAKE=3.25.1 run user 1
expect user out "run it as root"

[ $failures = 0 ] && echo "install_grader.sh: Ubuntu 22.04's versions refused with one message, PyPI CMake for 3.22, Debian 12's CMake used, a user refused"
exit $(( failures > 0 ))
