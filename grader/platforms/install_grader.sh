#!/usr/bin/env bash
# Installs what the grader needs on a grading machine and builds only that (make grader: t10-grade, the
# reference stages, FLIP). The one install step of every platform image: Gradescope's setup.sh, the
# Dockerfile for PrairieLearn's external grader and Gradescope's manual Docker route.
#   usage: install_grader.sh CHECKOUT        (as root: it runs apt-get)
# The project targets Debian 12 and 13. On another apt-based image (Gradescope's Ubuntu bases) it checks,
# before building, that the release has every package the grader needs, in the versions it needs, and
# supplies what can come from a registry reachable at image build time: CMake from PyPI (into
# $T10_CMAKE_VENV, default /opt/t10-cmake) when the system's is older than the presets need (3.25).
# What the release lacks otherwise is listed in one message, with the base image to choose instead,
# and the script exits 1.
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

release=$( (. /etc/os-release && echo "${PRETTY_NAME:-$ID $VERSION_ID}") 2>/dev/null || echo "an unknown release")
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
# OpenEXR 3 (Debian 12 has 3.1; Ubuntu 22.04 has 2.5, whose API and CMake package differ).
exr=$(candidate libopenexr-dev)
if [ -n "$exr" ] && [ "$exr" != "(none)" ] && dpkg --compare-versions "$exr" lt 3; then
    too_old+=("libopenexr-dev $exr (OpenEXR 3 is needed)")
fi
if [ ${#missing[@]} -gt 0 ] || [ ${#too_old[@]} -gt 0 ]; then
    say "$release cannot build the grader from its own packages:" >&2
    [ ${#missing[@]} -eq 0 ] || say "  not in this release: ${missing[*]}" >&2
    for t in "${too_old[@]}"; do say "  too old: $t" >&2; done
    say "choose a base image with Debian 12 or 13, or Ubuntu 24.04 (on Gradescope: the base image selector)" >&2
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

make -C "$checkout" --no-print-directory grader JOBS="${JOBS:-$(nproc)}"
say "built $checkout/build/bin/t10-grade"
