#!/usr/bin/env bash
# Installs what the grader needs on a grading machine and builds only that (make grader: t10-grade, the
# reference stages, FLIP). The one install step of every platform image: Gradescope's setup.sh, the
# Dockerfile for PrairieLearn's external grader and Gradescope's manual Docker route.
#   usage: install_grader.sh CHECKOUT        (as root: it runs apt-get)
# Debian 12 and 13 and Ubuntu 22.04 (Gradescope's default image) and 24.04 build the grader from their
# own packages (make grader-packages). On any apt-based release it checks first that every package is
# there, in a version the grader builds with (OpenEXR 2.5, g++ 10), and supplies what can come from a
# registry reachable at image build time: CMake from PyPI (into $T10_CMAKE_VENV, default /opt/t10-cmake)
# when the system's is older than the presets need (3.25; Ubuntu 22.04 has 3.22). What a release lacks
# otherwise is listed in one message, with the base images that work, and the script exits 1.
# After the build the reference stages' folders and the TGA reference PNGs are closed to other users: where the grader cannot
# have user namespaces (Gradescope, most Docker hosts) it runs each job as its own uid, which sees what
# others may read.
# Exit 0 when the grader is built; 1 when it cannot be; 2 on bad usage.
set -euo pipefail
if [ $# -ne 1 ] || [ ! -f "$1/Makefile" ]; then
    echo "usage: install_grader.sh CHECKOUT   (CHECKOUT: the project's checkout, with its Makefile)" >&2
    exit 2
fi
checkout=$(cd "$1" && pwd)
say() { echo "install_grader.sh: $*"; }
[ "$(id -u)" -eq 0 ] || { say "run it as root: it installs packages with apt-get" >&2; exit 1; }
command -v apt-get >/dev/null || { say "no apt-get here: the grader installs Debian or Ubuntu packages" >&2; exit 1; }

# T10_OS_RELEASE: another os-release file (grader/tests/platforms/install_check.sh plays other releases).
os_release=${T10_OS_RELEASE:-/etc/os-release}
release=$( (. "$os_release" && echo "${PRETTY_NAME:-$ID $VERSION_ID}") 2>/dev/null || echo "an unknown release")
say "installing on $release"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# make first: the Makefile holds the package list (make grader-packages), so that it is written once.
apt-get install -y -qq --no-install-recommends make ca-certificates >/dev/null
read -r -a packages <<<"$(make -s -C "$checkout" --no-print-directory grader-packages)"

# What this release lacks, and what it has in a version too old for the grader.
missing=()
for p in "${packages[@]}"; do
    apt-cache show --no-all-versions "$p" >/dev/null 2>&1 || missing+=("$p")
done
candidate() { apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: *//p'; }
too_old=()
# older_than PACKAGE VERSION WHY: the release's candidate of PACKAGE is older than VERSION.
older_than() {
    local have
    have=$(candidate "$1")
    if [ -n "$have" ] && [ "$have" != "(none)" ] && dpkg --compare-versions "$have" lt "$2"; then
        too_old+=("$1 $have ($3)")
    fi
}
# OpenEXR 2.5 (Ubuntu 22.04, Debian 11) or 3: the Imf API the code uses; cmake/T10OpenEXR.cmake takes either package.
older_than libopenexr-dev 2.5 "OpenEXR 2.5 or later is needed"
# g++ 10 (C++17 with <filesystem> and <charconv> for integers); the meta-package's version has epoch 4.
older_than g++ 4:10 "g++ 10 or later is needed"
if [ ${#missing[@]} -gt 0 ] || [ ${#too_old[@]} -gt 0 ]; then
    say "$release cannot build the grader from its own packages:" >&2
    if [ ${#missing[@]} -gt 0 ]; then
        say "  not in this release: ${missing[*]}" >&2
        # Ubuntu keeps most of them in universe, which a trimmed image may leave out of its sources.
        if (. "$os_release" 2>/dev/null && [ "${ID:-}" = ubuntu ]); then
            say "  (on Ubuntu they are in the universe component: is it in /etc/apt/sources.list?)" >&2
        fi
    fi
    for t in "${too_old[@]}"; do say "  too old: $t" >&2; done
    say "choose a base image with Ubuntu 22.04 or 24.04, or Debian 12 or 13 (on Gradescope: the base image selector)" >&2
    exit 1
fi
say "installing ${#packages[@]} packages: ${packages[*]}"
apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null

# CMake: the presets are version 6 and CMakeLists.txt asks for 3.25.
need=3.25
have=$(cmake --version 2>/dev/null | sed -n 's/^cmake version \([0-9.]*\).*/\1/p')
if [ -z "$have" ] || dpkg --compare-versions "$have" lt "$need"; then
    venv=${T10_CMAKE_VENV:-/opt/t10-cmake}
    say "CMake ${have:-(none)} is older than $need: installing CMake from PyPI into $venv"
    apt-get install -y -qq --no-install-recommends python3-venv >/dev/null
    python3 -m venv "$venv"
    # Pinned: the release the project was checked with.
    "$venv/bin/pip" install --quiet --disable-pip-version-check 'cmake==3.31.6'
    export PATH=$venv/bin:$PATH
    have=$(cmake --version | sed -n 's/^cmake version \([0-9.]*\).*/\1/p')
fi
say "CMake $have, $(c++ --version | head -n 1)"

# The grader's sandbox passes bubblewrap --size (0.8 and later); an older one (Ubuntu 22.04: 0.6.1) is
# refused at the grader's probe, which then isolates by uid, as it does where namespaces are not allowed.
bwrap_version=$(bwrap --version 2>/dev/null | sed -n 's/^bubblewrap \([0-9.]*\).*/\1/p')
if [ -n "$bwrap_version" ] && dpkg --compare-versions "$bwrap_version" lt 0.8; then
    say "bubblewrap $bwrap_version is older than 0.8: the grader will run each job as its own uid (--isolation uid)"
fi

make -C "$checkout" --no-print-directory grader JOBS="${JOBS:-$(nproc)}"
say "built $checkout/build/bin/t10-grade"

# The reference stages (each part's answer), extras/ (Part 3's with the exercises) and the TGA exercise's
# reference PNGs (tests/fixtures/tga: t10-grade-tga copies the inputs in as root) closed to other users,
# so that a job's uid cannot read the answers; the grader, as root, still reads them.
closed=()
for dir in "$checkout"/tutorial10_part[1-9]_* "$checkout/extras" "$checkout/tests/fixtures/tga"; do
    [ -d "$dir" ] || continue
    chmod go-rwx "$dir"
    closed+=("${dir#"$checkout"/}")
done
say "closed to other users: ${closed[*]}"
