#!/usr/bin/env bash
# Tests install_grader.sh's decisions without installing anything: apt-get, apt-cache, bwrap, cmake, c++,
# id, python3 and make grader are stand-ins (on PATH before the system's) that play a release's packages
# and log what they are asked, and the release's os-release file is written here (T10_OS_RELEASE). The
# script runs on a copy of the Makefile (make grader-packages is real) with empty stage folders, whose
# modes are checked afterwards. Cases:
#   jammy     Ubuntu 22.04's versions (OpenEXR 2.5.7, g++ 11, CMake 3.22.1, bubblewrap 0.6.1): builds, with
#             CMake from PyPI (pinned), says the grader will isolate by uid, closes the reference stages
#   old       an Ubuntu 20.04-like release (OpenEXR 2.3, g++ 9, no libtinygltf-dev): stops before any
#             install with one message naming each, universe and the base images that work
#   bookworm  Debian 12: builds with the system's CMake 3.25, no PyPI, no uid note (bubblewrap 0.8)
#   user      not root: refused
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
  policy) case "$2" in libopenexr-dev) echo "  Candidate: $STUB_EXR" ;; g++) echo "  Candidate: $STUB_GXX" ;; esac ;;
esac'
stub bwrap 'echo "bubblewrap $STUB_BWRAP"'
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
# run NAME EXPECTED_EXIT OS_RELEASE_LINES: runs the script with the STUB_* settings in the environment on
# a fresh copy of the checkout's Makefile with open stage folders.
run() {
    log=$out/$1.log
    : > "$log"
    copy=$out/$1-checkout
    mkdir -p "$copy/tutorial10_part0_start" "$copy/tutorial10_part3_gaussian" "$copy/extras" "$copy/common" "$copy/tests/fixtures/tga"
    chmod 755 "$copy"/*
    cp "$checkout/Makefile" "$copy/Makefile"
    printf '%s\n' "$3" > "$out/$1.os-release"
    STUB_LOG=$log PATH=$out/bin:$PATH T10_CMAKE_VENV=$out/$1-venv T10_OS_RELEASE=$out/$1.os-release \
        bash "$script" "$copy" > "$out/$1.out" 2>&1
    code=$?
    [ "$code" = "$2" ] || { echo "FAIL $1: exit $code, expected $2"; cat "$out/$1.out"; failures=$((failures + 1)); }
}
expect() { # expect CASE FILE(out|log) WORDS [absent]
    if grep -qF -- "$3" "$out/$1.$2"; then found=1; else found=0; fi
    if [ "${4:-}" = absent ]; then [ $found = 0 ] || { echo "FAIL $1: '$3' in its $2"; failures=$((failures + 1)); }
    else [ $found = 1 ] || { echo "FAIL $1: no '$3' in its $2:"; cat "$out/$1.$2"; failures=$((failures + 1)); }; fi
}
mode() { # mode CASE FOLDER EXPECTED: the octal mode of a folder of the case's checkout copy
    local got
    got=$(stat -c %a "$out/$1-checkout/$2")
    [ "$got" = "$3" ] || { echo "FAIL $1: $2 has mode $got, expected $3"; failures=$((failures + 1)); }
}

STUB_MISSING= STUB_EXR=2.5.7-1 STUB_GXX=4:11.2.0-1ubuntu1 STUB_CMAKE=3.22.1 STUB_BWRAP=0.6.1 \
    run jammy 0 'PRETTY_NAME="Ubuntu 22.04.5 LTS"
ID=ubuntu'
expect jammy out "installing on Ubuntu 22.04.5 LTS"
expect jammy out "cannot build" absent
expect jammy log "install -y -qq --no-install-recommends cmake ninja-build"
expect jammy log "libopenexr-dev zlib1g-dev"
expect jammy log "libimgui-dev" absent
expect jammy out "CMake 3.22.1 is older than 3.25: installing CMake from PyPI"
expect jammy log "pip install --quiet --disable-pip-version-check cmake==3.31.6"
expect jammy out "bubblewrap 0.6.1 is older than 0.8: the grader will run each job as its own uid"
expect jammy log "--no-print-directory grader"
expect jammy log "with cmake version 3.31.6"
expect jammy out "closed to other users: tutorial10_part3_gaussian extras tests/fixtures/tga"
mode jammy tutorial10_part3_gaussian 700
mode jammy extras 700
mode jammy tests/fixtures/tga 700
mode jammy tutorial10_part0_start 755
mode jammy common 755

STUB_MISSING=libtinygltf-dev STUB_EXR=2.3.0-6ubuntu0.5 STUB_GXX=4:9.3.0-1ubuntu2 STUB_CMAKE=3.16.3 STUB_BWRAP=0.4.0 \
    run old 1 'PRETTY_NAME="Ubuntu 20.04.6 LTS"
ID=ubuntu'
expect old out "Ubuntu 20.04.6 LTS cannot build the grader from its own packages"
expect old out "not in this release: libtinygltf-dev"
expect old out "universe component"
expect old out "too old: libopenexr-dev 2.3.0-6ubuntu0.5 (OpenEXR 2.5 or later is needed)"
expect old out "too old: g++ 4:9.3.0-1ubuntu2 (g++ 10 or later is needed)"
expect old out "Ubuntu 22.04 or 24.04, or Debian 12 or 13"
expect old log "install -y -qq --no-install-recommends cmake" absent
expect old log "grader JOBS" absent
mode old tutorial10_part3_gaussian 755

STUB_MISSING= STUB_EXR=3.1.5-5 STUB_GXX=4:12.2.0-3 STUB_CMAKE=3.25.1 STUB_BWRAP=0.8.0 \
    run bookworm 0 'PRETTY_NAME="Debian GNU/Linux 12 (bookworm)"
ID=debian'
expect bookworm log "pip install" absent
expect bookworm log "with cmake version 3.25.1"
expect bookworm log "install -y -qq --no-install-recommends cmake ninja-build"
expect bookworm out "own uid" absent
mode bookworm tutorial10_part3_gaussian 700

STUB_UID=1000 STUB_MISSING= STUB_EXR=3.1.5 STUB_GXX=4:12.2.0-3 STUB_CMAKE=3.25.1 STUB_BWRAP=0.8.0 \
    run user 1 'ID=debian'
expect user out "run it as root"

[ $failures = 0 ] && echo "install_grader.sh: Ubuntu 22.04 builds (PyPI CMake, uid isolation noted, reference stages closed), an older release refused with one message, Debian 12's CMake used, a user refused"
exit $(( failures > 0 ))
