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
    apt-get source -qq "$package" >/dev/null
done
