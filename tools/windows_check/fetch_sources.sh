#!/usr/bin/env bash
# Fetches Debian's source packages of the libraries the Windows build compiles itself (GLFW, Imath,
# OpenEXR, Dear ImGui) into DEST/src/, through a private apt configuration under DEST/apt/ with a
# deb-src entry, so the machine's own apt setup is left alone.
# usage: fetch_sources.sh DEST PACKAGE...
set -euo pipefail
dest=$1
shift
apt_dir=$dest/apt
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$dest/src"
apt_dir=$(cd "$apt_dir" && pwd)
# The suites the machine installs from (its own sources), as deb-src.
suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
printf 'deb-src http://deb.debian.org/debian %s main\n' "$suite" >"$apt_dir/sources.list"
cat >"$apt_dir/apt.conf" <<CONF
Dir::Etc::SourceList "$apt_dir/sources.list";
Dir::Etc::SourceParts "$apt_dir/none";
Dir::State::Lists "$apt_dir/lists";
Dir::Cache "$apt_dir/cache";
APT::Sandbox::User "root";
CONF
export APT_CONFIG=$apt_dir/apt.conf
[ -n "$(ls "$apt_dir/lists" 2>/dev/null | grep Sources)" ] || apt-get update -qq
cd "$dest/src"
for package in "$@"; do
    if ls -d "$package"-*/ >/dev/null 2>&1; then continue; fi
    if ! out=$(apt-get source -qq "$package" 2>&1 >/dev/null); then
        echo "$out" | tail -n 5 >&2
        # An archive that cannot be reached, or a mirror that does not carry the source files its own
        # index lists (404), is the host's limit, not a broken Windows build: exit 77 so that
        # windows_check.sh can say SKIPPED. Any other failure is ours.
        if echo "$out" | grep -qE ' 404 |Could not resolve|Temporary failure|Connection (timed out|refused)|Unable to connect'; then
            echo "fetch_sources: Debian's archive here does not give the source package $package" >&2
            exit 77
        fi
        echo "fetch_sources: apt-get source $package failed" >&2
        exit 1
    fi
done
