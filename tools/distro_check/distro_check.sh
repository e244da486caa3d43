#!/usr/bin/env bash
# make distro-check DISTRO=bookworm|trixie [MODES="root user"]: the README's two commands, `make run` and
# `make test`, run as a new user would in a fresh minimal Debian root: built once with mmdebstrap from
# Debian's archive and cached as CACHE/<distro>/base.tar, unpacked anew for each mode, with a clone of
# the checkout (its committed HEAD) in it. Mode `root` runs them as root from /root/tutorial10; mode `user`
# as the user `student` (sudo without a password) from /home/student/tutorial10. Prints each command's
# exit status and time, and ctest's summary; the logs and the unpacked roots stay in CACHE/<distro>/.
#
# The root is entered with pivot_root in new mount and PID namespaces, not chroot: the kernel refuses
# user namespaces (bwrap, the grader's sandbox) to a chrooted process. It shares the host's network and
# gets the host's CA bundle, apt Acquire settings and pip configuration (/etc/pip.conf and the PIP_*
# variables), so that it reaches the same registries as the host.
# usage: distro_check.sh DISTRO "MODES" SOURCE_CHECKOUT CACHE_DIR ["TARGETS"]
#   MODES=none only builds the root; TARGETS (default "run test") are the make targets run in turn.
# A host that cannot do this at all (no mount or user namespaces for root, pivot_root refused, the
# Debian archive unreachable) gets "SKIPPED: <reason>" and exit 0; a failing make target exits 1.
set -euo pipefail

distro=${1:-} modes=${2:-root user} source=${3:-.} cache=${4:-build/distro-check} targets=${5:-run test}
case "$distro" in
    bookworm|trixie) ;;
    *) echo "distro-check: DISTRO='$distro': choose bookworm (Debian 12) or trixie (Debian 13)" >&2; exit 2 ;;
esac
for mode in $modes; do
    case "$mode" in root|user|none) ;; *) echo "distro-check: MODES: '$mode' is neither root nor user" >&2; exit 2 ;; esac
done
[ "$(id -u)" -eq 0 ] || { echo "distro-check: needs root (mmdebstrap, mount namespaces, pivot_root)" >&2; exit 2; }
command -v mmdebstrap >/dev/null || { echo "distro-check: mmdebstrap is not installed (make distro-check installs it)" >&2; exit 2; }
for target in $targets; do
    case "$target" in [a-z]*) ;; *) echo "distro-check: TARGETS: '$target' is not a make target" >&2; exit 2 ;; esac
done
skip() { echo "SKIPPED: make distro-check DISTRO=$distro: $1"; exit 0; }
# What the host must allow: new mount and PID namespaces with pivot_root (to enter the root) and user
# namespaces (bwrap, the grader's sandbox, inside it).
unshare --mount --pid --fork --propagation private true 2>/dev/null ||
    skip "this host refuses new mount/PID namespaces (unshare --mount --pid)"
unshare --user --map-root-user true 2>/dev/null || skip "this host refuses user namespaces (unshare --user)"
source=$(cd "$source" && git rev-parse --show-toplevel) || { echo "distro-check: $3: not a git checkout" >&2; exit 2; }
mkdir -p "$cache/$distro"
work=$(cd "$cache/$distro" && pwd -P)

# The host's apt Acquire settings (proxies, date checks) for mmdebstrap and for apt inside the root.
apt-config dump | grep -E '^Acquire::' >"$work/host-apt.conf" || true

base=$work/base.tar
if [ ! -f "$base" ]; then
    echo "distro-check: building a minimal $distro root with mmdebstrap into $base"
    start=$(date +%s)
    # minbase: Essential packages and apt. make is what the README's commands are typed into;
    # ca-certificates so that https works; sudo for the user mode. Everything else the project needs
    # must come from its own `make` targets.
    mmdebstrap --variant=minbase --include=make,ca-certificates,sudo --aptopt="$work/host-apt.conf" \
        --format=tar "$distro" "$work/base.part.tar" >"$work/mmdebstrap.log" 2>&1 || {
        rm -f "$work/base.part.tar"; tail -n 5 "$work/mmdebstrap.log"
        # Only an archive that cannot be reached is the host's; any other mmdebstrap failure is ours.
        if grep -qiE 'Could not resolve|Failed to fetch|Temporary failure|Connection (timed out|refused)|Unable to connect' "$work/mmdebstrap.log"; then
            skip "Debian's archive cannot be reached from this host (mmdebstrap: $work/mmdebstrap.log)"
        fi
        echo "distro-check: mmdebstrap failed (log $work/mmdebstrap.log)" >&2; exit 1; }
    mv "$work/base.part.tar" "$base"
    echo "distro-check: root built in $(( $(date +%s) - start )) s"
fi
mkdir -p "$work/apt-archives"
[ "$modes" != none ] || exit 0 # MODES=none: only build (or keep) the cached root

# passenv and enter ROOT USER COMMAND (tools/distro_check/enter.sh, shared with make devcontainer-check).
. "$(dirname "$0")/enter.sh"

# run MODE LABEL COMMAND: one timed command, its output into the mode's log; prints status and time.
status=0
run() {
    local mode=$1 label=$2 command=$3 user=root start rc ms
    [ "$mode" = root ] || user=student
    start=$(date +%s%N)
    set +e
    enter "$work/root-$mode" "$user" "$command" >>"$work/$mode.log" 2>&1
    rc=$?
    set -e
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    printf 'distro-check: %s, %s: %-12s exit %d, %d.%d s\n' "$distro" "$mode" "$label" "$rc" $((ms / 1000)) $((ms % 1000 / 100))
    return $rc
}

for mode in $modes; do
    root=$work/root-$mode
    log=$work/$mode.log
    rm -rf "$root" && mkdir -p "$root"
    tar -C "$root" -xf "$base"
    cp "$work/host-apt.conf" "$root/etc/apt/apt.conf.d/00host-acquire"
    : >"$log"
    if [ "$mode" = user ]; then
        useradd --root "$root" --create-home --shell /bin/bash --groups sudo student
        echo 'student ALL=(ALL) NOPASSWD: ALL' >"$root/etc/sudoers.d/student"
        chmod 0440 "$root/etc/sudoers.d/student"
        home=$root/home/student
    else
        home=$root/root
    fi
    # sudo resolves the host name it runs on.
    echo "127.0.1.1 $(hostname)" >>"$root/etc/hosts"
    git clone --quiet --no-hardlinks "$source" "$home/tutorial10"
    echo "distro-check: $distro, $mode: $(git -C "$home/tutorial10" log -1 --format='%h %s'), log $log"
    [ "$mode" = root ] || chown -R "$(grep '^student:' "$root/etc/passwd" | cut -d: -f3,4)" "$home"
    for target in $targets; do
        run "$mode" "make $target" "cd tutorial10 && make $target" || status=1
    done
    summary=$(grep -E 'tests passed|tests failed out of|Total Test time' "$log" | tail -n 2 || true)
    echo "${summary:-(no ctest summary in the log)}" | sed "s/^/distro-check: $distro, $mode: /"
    grep -E '^\s+[0-9]+ - .*\((Failed|Timeout|SEGFAULT|Not Run|Subprocess aborted)\)' "$log" | sed "s/^/distro-check: $distro, $mode: failed:/" || true
done
exit $status
