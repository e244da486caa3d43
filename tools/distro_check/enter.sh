# Sourced by distro_check.sh and tools/devcontainer_check/: how a command enters an unpacked Debian
# root. `enter ROOT USER COMMAND` runs COMMAND (a bash command line) in ROOT as USER (root, or an
# account of the root: from its home), with pivot_root in new mount and PID namespaces, not chroot
# (the kernel refuses user namespaces, the grader's sandbox, to a chrooted process). It shares the
# host's network and gets the host's CA bundle, resolver, apt archive cache (ROOT/../apt-archives) and
# pip configuration; with ENTER_NET=isolated it gets a network namespace of its own with only the
# loopback (servers in the root then cannot clash with the host's ports). Every process of the root
# dies when COMMAND returns (the PID namespace ends). Needs root and the host's `ip` for ENTER_NET.

# The environment the commands run with: a login's, plus the host's pip and CA variables.
passenv=(HOME="" PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 TERM=dumb)
while IFS='=' read -r name value; do
    case "$name" in
        PIP_*|SSL_CERT_FILE|SSL_CERT_DIR|REQUESTS_CA_BUNDLE|CURL_CA_BUNDLE|GIT_SSL_CAINFO|http_proxy|https_proxy|no_proxy|HTTP_PROXY|HTTPS_PROXY|NO_PROXY)
            passenv+=("$name=$value") ;;
    esac
done < <(env)

enter() {
    local root=$1 user=$2 command=$3 home=/root net=()
    [ "$user" = root ] || home=/home/$user
    [ "${ENTER_NET:-}" != isolated ] || net=(--net)
    unshare --mount --pid --fork --propagation private "${net[@]}" -- /bin/bash -s "$root" "$user" "$home" "$command" "${ENTER_NET:-}" "${passenv[@]}" <<'INNER'
set -eu
root=$1 user=$2 home=$3 command=$4 net=$5
shift 5
[ "$net" != isolated ] || ip link set lo up
mount --bind "$root" "$root"
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mount --rbind /sys "$root/sys"
mount -t tmpfs -o mode=1777 tmpfs "$root/tmp"
mount --bind "$(dirname "$root")/apt-archives" "$root/var/cache/apt/archives"
# The host's CA bundle, resolver and pip configuration (copied, so the root's own files stay its own).
cp -L /etc/resolv.conf "$root/etc/resolv.conf"
mkdir -p "$root/etc/ssl/certs"
cp -L /etc/ssl/certs/ca-certificates.crt "$root/etc/ssl/certs/ca-certificates.crt"
[ ! -f /etc/pip.conf ] || cp -L /etc/pip.conf "$root/etc/pip.conf"
# The host's own CAs too, where the root's stores are made from them: Java's keystore (ca-certificates-java,
# which Maven uses) is built from the root's certificates, not from the bundle above, so a host that
# trusts a local CA (a proxy's) must hand it on for mvn to reach Maven Central; update-ca-certificates runs
# below, inside the root.
local_cas=$(find /usr/local/share/ca-certificates -name '*.crt' 2>/dev/null | head -n 1)
if [ -n "$local_cas" ]; then
    mkdir -p "$root/usr/local/share/ca-certificates"
    find /usr/local/share/ca-certificates -name '*.crt' -exec cp -L {} "$root/usr/local/share/ca-certificates/" \;
fi
if [ -n "${PIP_FIND_LINKS:-}" ] && [ -d "$PIP_FIND_LINKS" ]; then
    mkdir -p "$root$PIP_FIND_LINKS" && mount --bind -o ro "$PIP_FIND_LINKS" "$root$PIP_FIND_LINKS"
fi
cd "$root"
mkdir -p .host
pivot_root . .host
umount -l /.host
rmdir /.host
cd /
if [ -n "$local_cas" ] && command -v update-ca-certificates >/dev/null; then
    update-ca-certificates >/dev/null 2>&1 || echo "enter: update-ca-certificates failed in the root: the host's own CAs are not trusted there" >&2
fi
env=()
for kv in "$@"; do
    case "$kv" in HOME=*) env+=("HOME=$home") ;; *) env+=("$kv") ;; esac
done
[ "$user" = root ] || env+=("USER=$user" "LOGNAME=$user")
if [ "$user" = root ]; then exec env -i "${env[@]}" /bin/bash -c "cd && $command"; fi
exec runuser -u "$user" -- env -i "${env[@]}" /bin/bash -c "cd && $command"
INNER
}
