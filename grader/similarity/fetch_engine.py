#!/usr/bin/env python3
"""Fetches the jars of jplag.lock from Maven Central into ENGINE_DIR/lib/ (make similarity-deps).

usage: fetch_engine.py LOCK ENGINE_DIR [--check]

Each jar is downloaded to a temporary name, its size and SHA-256 checked against the lock, then renamed
into place; a jar already there with the right hash is kept, so a second run fetches nothing. Jars the
lock no longer names are removed. ENGINE_DIR/lock is a copy of the lock written last: similarity.py
compares it with the checkout's lock and refuses a stale or partial engine. --check fetches nothing and
exits 1 naming what is missing or wrong. Exit 0 when every jar is in place.
"""
import hashlib
import os
import shutil
import sys
import urllib.request

CENTRAL = "https://repo1.maven.org/maven2"


def read_lock(path):
    """[(group, artifact, version, size, sha256)] of the lock; SystemExit naming a malformed line."""
    entries = []
    with open(path, encoding="utf-8") as lock:
        for number, line in enumerate(lock, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            fields = line.split()
            coords = fields[0].split(":") if fields else []
            if len(fields) != 3 or len(coords) != 3 or not fields[1].isdigit() or len(fields[2]) != 64:
                sys.exit(f"{path}:{number}: expected 'group:artifact:version size sha256', got: {line}")
            entries.append((*coords, int(fields[1]), fields[2].lower()))
    if not entries:
        sys.exit(f"{path}: names no jar")
    return entries


def jar_name(artifact, version):
    return f"{artifact}-{version}.jar"


def digest(path):
    sha = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            sha.update(block)
    return sha.hexdigest()


def fetch(group, artifact, version, size, sha, lib):
    url = f"{CENTRAL}/{group.replace('.', '/')}/{artifact}/{version}/{jar_name(artifact, version)}"
    target = os.path.join(lib, jar_name(artifact, version))
    partial = target + ".partial"
    try:
        with urllib.request.urlopen(url, timeout=60) as response, open(partial, "wb") as out:
            shutil.copyfileobj(response, out)
    except OSError as error:
        sys.exit(f"fetch_engine: {url}: {error}")
    got_size, got_sha = os.path.getsize(partial), digest(partial)
    if got_size != size or got_sha != sha:
        os.unlink(partial)
        sys.exit(f"fetch_engine: {url}: {got_size} bytes, sha256 {got_sha}; the lock says {size} bytes, {sha}")
    os.replace(partial, target)


def main():
    args = [a for a in sys.argv[1:] if a != "--check"]
    if len(args) != 2:
        sys.exit(__doc__.split("\n\n")[1])
    lock_path, engine = args
    check = "--check" in sys.argv[1:]
    entries = read_lock(lock_path)
    lib = os.path.join(engine, "lib")
    wanted = {jar_name(a, v) for _, a, v, _, _ in entries}
    problems = []
    if not check:
        os.makedirs(lib, exist_ok=True)
        for name in os.listdir(lib):
            if name not in wanted:
                os.unlink(os.path.join(lib, name))
    for group, artifact, version, size, sha in entries:
        path = os.path.join(lib, jar_name(artifact, version))
        if os.path.isfile(path) and os.path.getsize(path) == size and digest(path) == sha:
            continue
        if check:
            problems.append(f"{path}: missing or not the jar of the lock")
        else:
            fetch(group, artifact, version, size, sha, lib)
    if problems:
        sys.exit("\n".join(problems))
    if not check:
        shutil.copyfile(lock_path, os.path.join(engine, "lock.partial"))
        os.replace(os.path.join(engine, "lock.partial"), os.path.join(engine, "lock"))
        print(f"JPlag {entries[0][2]}: {len(entries)} jars in {lib}, each checked against {lock_path}")


if __name__ == "__main__":
    main()
