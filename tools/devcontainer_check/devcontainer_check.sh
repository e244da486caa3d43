#!/usr/bin/env bash
# make devcontainer-check: the dev container (.devcontainer/) proven without Docker. The Dockerfile's
# steps (dockerfile_steps.py reads them) run in a fresh minimal Debian 12 root made by mmdebstrap, as
# Docker's debian:bookworm image is (Debian's minbase); the resulting "image" is cached as
# CACHE/image.tar, keyed by the hash of the files it is made from, and remade when they change. Then,
# in a fresh copy of it, with a clone of the checkout's HEAD at /workspaces/tutorial10 (as Codespaces
# places a repository) and the image's ENV:
#   postCreateCommand as the container's user (devcontainer.json's, with the network), then inside.sh
#   as that user with a network of its own: postStartCommand (the desktop), glxinfo -B through it,
#   make run's window (a screenshot), noVNC's page in headless Chromium (a screenshot compared with the
#   desktop's), make check PART=1 after make student PART=1, and make check under Docker's default
#   seccomp profile (the clear refusal, then ISOLATION=none).
# Prints each step's result and time, the image's build time and size, and the screenshots' paths
# (CACHE/out/). The roots are entered as make distro-check enters its own (tools/distro_check/enter.sh).
#   usage: devcontainer_check.sh SOURCE_CHECKOUT CACHE_DIR
# A host that cannot do this at all (no namespaces, Debian's archive unreachable) gets "SKIPPED:
# <reason>" and exit 0; a failing step exits 1.
set -euo pipefail
source=${1:-.} cache=${2:-build/devcontainer-check}
here=$(cd "$(dirname "$0")" && pwd)
[ "$(id -u)" -eq 0 ] || { echo "devcontainer-check: needs root (mmdebstrap, mount namespaces, pivot_root)" >&2; exit 2; }
for tool in mmdebstrap ip git; do
    command -v $tool >/dev/null || { echo "devcontainer-check: $tool is not installed (make devcontainer-check installs it)" >&2; exit 2; }
done
skip() { echo "SKIPPED: make devcontainer-check: $1"; exit 0; }
unshare --mount --pid --net --fork --propagation private true 2>/dev/null ||
    skip "this host refuses new mount/PID/network namespaces (unshare --mount --pid --net)"
unshare --user --map-root-user true 2>/dev/null || skip "this host refuses user namespaces (unshare --user)"
source=$(cd "$source" && git rev-parse --show-toplevel) || { echo "devcontainer-check: $1: not a git checkout" >&2; exit 2; }
mkdir -p "$cache"
work=$(cd "$cache" && pwd -P)
log=$work/check.log
: >"$log"
. "$here/../distro_check/enter.sh"

# elapsed START: seconds since START (date +%s%N) as N.N.
elapsed() { local ms=$(( ($(date +%s%N) - $1) / 1000000 )); echo "$((ms / 1000)).$((ms % 1000 / 100))"; }

# The build context: the checkout's committed HEAD, as Codespaces clones it.
rm -rf "$work/context"
git clone --quiet --no-hardlinks "$source" "$work/context"
echo "devcontainer-check: $(git -C "$work/context" log -1 --format='%h %s'), log $log"
dockerfile=$work/context/.devcontainer/Dockerfile
mapfile -d '' steps < <(python3 "$here/dockerfile_steps.py" "$dockerfile")
[ ${#steps[@]} -gt 0 ] || { python3 "$here/dockerfile_steps.py" "$dockerfile" >/dev/null; exit 1; }

apt-config dump | grep -E '^Acquire::' >"$work/host-apt.conf" || true
base=$work/base.tar
if [ ! -f "$base" ]; then
    start=$(date +%s%N)
    # minbase, nothing more: what Docker's debian:bookworm holds. The Dockerfile installs the rest.
    mmdebstrap --variant=minbase --aptopt="$work/host-apt.conf" --format=tar bookworm "$work/base.part.tar" \
        >"$work/mmdebstrap.log" 2>&1 || {
        rm -f "$work/base.part.tar"; tail -n 5 "$work/mmdebstrap.log"
        if grep -qiE 'Could not resolve|Failed to fetch|Temporary failure|Connection (timed out|refused)|Unable to connect' "$work/mmdebstrap.log"; then
            skip "Debian's archive cannot be reached from this host (mmdebstrap: $work/mmdebstrap.log)"
        fi
        echo "devcontainer-check: mmdebstrap failed (log $work/mmdebstrap.log)" >&2; exit 1; }
    mv "$work/base.part.tar" "$base"
    echo "devcontainer-check: Debian 12 minbase root (mmdebstrap) built in $(elapsed "$start") s"
fi
mkdir -p "$work/apt-archives"

# The container user's uid, as `docker build --build-arg USER_UID=N` would set it: the root shares the
# host's kernel, which counts a uid's processes across the machine (RLIMIT_NPROC, the grader's limit),
# so the check takes one that no host account or process uses (the Dockerfile's own default is 1000).
uid=20000
while getent passwd $uid >/dev/null || [ -n "$(ps -o pid= -u $uid 2>/dev/null)" ]; do uid=$((uid + 1)); done
build_args=("USER_UID=$uid")
# The image's key: the build arguments, the Dockerfile and every file it copies. mapfile splits each record at its NULs,
# so a COPY is three elements (COPY, source, dest), every other instruction two.
key=$( { echo "${build_args[@]}"; sha256sum "$dockerfile"; i=0; while [ $i -lt ${#steps[@]} ]; do
    if [ "${steps[i]}" = COPY ]; then sha256sum "$work/context/${steps[i + 1]}"; i=$((i + 1)); fi
    i=$((i + 2)); done; } | sha256sum | cut -d' ' -f1)
root=$work/root
user=root workdir=/ envs=() cmd=""
image=$work/image.tar
# build_arg NAME=DEFAULT: NAME=VALUE with VALUE from build_args where it names NAME.
build_arg() {
    local given
    for given in "${build_args[@]}"; do [ "${given%%=*}" != "${1%%=*}" ] || { echo "$given"; return; }; done
    echo "$1"
}
run_steps() {
    local i=0 kind arg
    while [ $i -lt ${#steps[@]} ]; do
        kind=${steps[i]} arg=${steps[i + 1]}
        i=$((i + 2))
        case $kind in
            FROM) [ "$arg" = debian:bookworm ] || { echo "devcontainer-check: FROM $arg: this check makes debian:bookworm only" >&2; return 1; } ;;
            ARG) envs+=("$(build_arg "$arg")") ;;
            ENV) envs+=("$arg") ;;
            COPY)
                local dest=${steps[i]}
                i=$((i + 1))
                mkdir -p "$(dirname "$root$dest")"
                cp -a "$work/context/$arg" "$root$dest" && chown root:root "$root$dest" ;;
            RUN)
                local exports="" kv
                for kv in "${envs[@]}"; do exports+="export $(printf '%q' "$kv"); "; done
                echo "+ RUN $arg" >>"$log"
                if ! enter "$root" "$user" "$exports cd $(printf '%q' "$workdir") && /bin/sh -c $(printf '%q' "$arg")" >>"$log" 2>&1; then
                    echo "devcontainer-check: the Dockerfile's step failed: RUN $arg (log $log)" >&2; return 1
                fi ;;
            USER) user=$arg ;;
            WORKDIR) workdir=$arg ;;
            CMD) cmd=$arg ;;
        esac
    done
}
if [ -f "$image" ] && [ "$(cat "$work/image.key" 2>/dev/null)" = "$key" ]; then
    rm -rf "$root" && mkdir -p "$root" && tar -C "$root" -xf "$image"
    # The steps again for their USER, ENV and CMD only (no RUN, no COPY: the image holds them).
    run_steps() { local i=0; while [ $i -lt ${#steps[@]} ]; do case ${steps[i]} in
        ARG) envs+=("$(build_arg "${steps[i + 1]}")") ;; ENV) envs+=("${steps[i + 1]}") ;; USER) user=${steps[i + 1]} ;; WORKDIR) workdir=${steps[i + 1]} ;;
        CMD) cmd=${steps[i + 1]} ;; COPY) i=$((i + 1)) ;; esac; i=$((i + 2)); done; }
    run_steps
    echo "devcontainer-check: image: cached ($(cat "$work/image.txt"))"
else
    rm -rf "$root" "$image" && mkdir -p "$root" && tar -C "$root" -xf "$base"
    cp "$work/host-apt.conf" "$root/etc/apt/apt.conf.d/00host-acquire"
    start=$(date +%s%N)
    run_steps
    seconds=$(elapsed "$start")
    size=$(du -sm --one-file-system "$root" | cut -f1)
    tar -C "$root" -cf "$image.part" . && mv "$image.part" "$image"
    echo "$key" >"$work/image.key"
    echo "built in $seconds s, $size MiB, $(date -u +%Y-%m-%dT%H:%MZ)" >"$work/image.txt"
    echo "devcontainer-check: image: the Dockerfile's steps took $seconds s; the root holds $size MiB"
fi
[ "$user" != root ] || { echo "devcontainer-check: the Dockerfile leaves the container's user root" >&2; exit 1; }
# /etc/hosts as Docker writes it into a container (sudo resolves the host name it runs on).
printf '127.0.0.1\tlocalhost\n::1\tlocalhost ip6-localhost ip6-loopback\n127.0.1.1\t%s\n' "$(hostname)" >"$root/etc/hosts"

# The image's environment for every command below (Docker gives ENV to the container's processes).
exports=""
for kv in "${envs[@]}"; do exports+="export $(printf '%q' "$kv"); "; done
# devcontainer.json's lifecycle commands, read as the schema test reads the file.
lifecycle() {
    PYTHONPATH="$work/context/tests/devcontainer" python3 -c 'import sys; import devcontainer_schema as d
value = d.load_jsonc(open(sys.argv[1]).read()).get(sys.argv[2], "")
print(value if isinstance(value, str) else " && ".join(value))' \
        "$work/context/.devcontainer/devcontainer.json" "$1"
}
post_create=$(lifecycle postCreateCommand)
post_start=$(lifecycle postStartCommand)

workspace=/workspaces/tutorial10
mkdir -p "$root/workspaces"
git clone --quiet --no-hardlinks "$source" "$root$workspace"
chown -R "$(grep "^$user:" "$root/etc/passwd" | cut -d: -f3,4)" "$root$workspace"
status=0
start=$(date +%s%N)
rc=0
enter "$root" "$user" "$exports cd $workspace && $post_create" >>"$log" 2>&1 || rc=$?
word=ok; [ $rc -eq 0 ] || { word="FAILED (exit $rc)"; status=1; }
printf 'devcontainer-check: %-22s %s, %s s\n' "postCreateCommand:" "$word ($post_create)" "$(elapsed "$start")"
echo "devcontainer-check: the root with the build holds $(du -sm --one-file-system "$root" | cut -f1) MiB"

# What only this check uses, not the image: xwd (x11-apps) and netpbm for the screenshots, and
# libseccomp's Python binding for Docker's seccomp profile.
enter "$root" root "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends x11-apps netpbm python3-seccomp" >>"$log" 2>&1 ||
    { echo "devcontainer-check: installing the check's own tools failed (log $log)" >&2; exit 1; }
mkdir -p "$root/opt/devcontainer-check/out" && cp "$here"/inside.sh "$here"/same_picture.py "$here"/docker_seccomp.py "$here"/novnc_screenshot.py "$root/opt/devcontainer-check/" &&
    mkdir -p "$root/opt/devcontainer-check/web" && cp "$here"/../web/__init__.py "$here"/../web/cdp.py "$root/opt/devcontainer-check/web/"
chown "$(grep "^$user:" "$root/etc/passwd" | cut -d: -f3,4)" "$root/opt/devcontainer-check/out"
rm -rf "$work/out"
if [ $status -eq 0 ]; then
    ENTER_NET=isolated enter "$root" "$user" "$exports cd $workspace && bash /opt/devcontainer-check/inside.sh /opt/devcontainer-check/out $(printf '%q' "$post_start")" 2>>"$log" |
        tee -a "$log" | grep '^devcontainer-check:' || status=1
    [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
fi
cp -a "$root/opt/devcontainer-check/out" "$work/out" 2>/dev/null || true
sed -n 's/^OpenGL core profile version string: /devcontainer-check: GL: /p; s/^OpenGL renderer string: /devcontainer-check: renderer: /p' "$work/out/glxinfo.txt" 2>/dev/null || true
echo "devcontainer-check: screenshots: $work/out/desktop.png (the desktop with make run's window), $work/out/novnc.png (noVNC's page in Chromium)"
[ $status -eq 0 ] && echo "devcontainer-check: passed" || echo "devcontainer-check: FAILED (log $log)"
exit $status
