#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (the zip is unpacked into
# $AUTOGRADER_ROOT/source, default /autograder/source). It installs what the grader needs and builds
# only that (install_grader.sh: make grader, t10-grade, the reference stages, FLIP in a venv). With T10_SOURCE=<checkout>
# (and T10_BUILD, default <checkout>/build) it reuses a checkout that is already built instead: that
# is how the tests run it outside a container. Then grades the reference stage (it must score 100), which
# also fills the grader's cache, and writes source/t10-location for run_autograder.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
here=$root/source
if [ -n "${T10_SOURCE:-}" ]; then
    build=${T10_BUILD:-$T10_SOURCE/build}
    for need in "$build/bin/t10-grade" "$build/grade-venv/bin/flip"; do
        [ -x "$need" ] || { echo "setup.sh: T10_SOURCE=$T10_SOURCE: $need is missing; run 'make grader' there first, or unset T10_SOURCE to build here" >&2; exit 1; }
    done
else
    T10_SOURCE=$here/t10
    build=$T10_SOURCE/build
    # The one install script of every platform image: it checks that this base image's release has
    # what the grader needs (stopping with the list of what it lacks and the base image to choose),
    # takes CMake from PyPI when the system's is too old, and runs make grader.
    "$T10_SOURCE/grader/platforms/install_grader.sh" "$T10_SOURCE"
fi
# Grade the reference stage once: it must score 100 here (proof that this image renders as the grader
# expects), and its renders and build stay in the grader's cache for every submission.
. "$here/t10.conf"
case "$T10_PART" in 1) stage=tutorial10_part1_tonemap ;; 2) stage=tutorial10_part2_bloom ;; *) stage=tutorial10_part3_gaussian ;; esac
warm=$(mktemp -d)
"$build/bin/t10-grade" --part "$T10_PART" --report "$warm" "$T10_SOURCE/$stage"
grep -q "^$stage,$T10_PART,graded,100," "$warm/gradebook.csv" || {
    echo "setup.sh: the reference $stage does not score 100 in this image:" >&2; cat "$warm/gradebook.csv" >&2; exit 1; }
rm -rf "$warm"
printf 'T10_SOURCE=%q\nT10_BUILD=%q\n' "$T10_SOURCE" "$build" > "$here/t10-location.tmp"
mv "$here/t10-location.tmp" "$here/t10-location"
echo "setup.sh: grading with $build/bin/t10-grade"
