#!/bin/sh
# t10-grade on a machine whose bubblewrap is older than the sandbox's options (Ubuntu 22.04 ships
# 0.6.1, which rejects --size): the run must name the old bubblewrap and the version it needs, not
# "no user namespaces". A fake /usr/bin/bwrap (it answers --version with 0.6.1 and rejects options
# as 0.6.1 does) is bound over the real one in a private mount namespace, so nothing else sees it.
#   old_bwrap.sh T10_GRADE SUBMISSION OUT_DIR
# Exit 0 when the message is right, 1 when not, 77 (skipped, saying why) without root or unshare.
set -u
grade=$1 submission=$2 out=$3
if [ "$(id -u)" != 0 ]; then echo "skipped: binding a fake bwrap over /usr/bin/bwrap needs root"; exit 77; fi
if ! command -v unshare >/dev/null || [ ! -e /usr/bin/bwrap ]; then echo "skipped: no unshare or no /usr/bin/bwrap to bind over"; exit 77; fi
if ! unshare -m sh -c 'mount --make-rprivate /' 2>/dev/null; then
    echo "skipped: no private mount namespace here (unshare -m fails: a container without CAP_SYS_ADMIN?)"; exit 77
fi
rm -rf "$out" && mkdir -p "$out" || exit 1
cat > "$out/bwrap" <<'FAKE'
#!/bin/sh
if [ "${1:-}" = --version ]; then echo "bubblewrap 0.6.1"; exit 0; fi
echo "bwrap: Unknown option --size" >&2
exit 1
FAKE
chmod 755 "$out/bwrap"
unshare -m sh -c 'mount --make-rprivate / && mount --bind "$1" /usr/bin/bwrap && exec "$2" --part 1 --isolation namespaces --report "$3" "$4"' \
    sh "$out/bwrap" "$grade" "$out/report" "$submission" > "$out/log" 2>&1
rc=$?
cat "$out/log"
want="bubblewrap 0.6.1 is too old for the sandbox (bwrap: Unknown option --size): namespaces isolation needs bubblewrap 0.8 or later"
if [ "$rc" = 0 ]; then echo "FAIL: exit 0 with a bubblewrap that cannot start the sandbox"; exit 1; fi
if ! grep -qF "$want" "$out/log"; then echo "FAIL: the message does not say: $want"; exit 1; fi
echo "ok: exit $rc, the old bubblewrap and the version needed named"
