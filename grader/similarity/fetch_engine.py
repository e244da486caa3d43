#!/usr/bin/env python3
"""Fetches the jars of jplag.lock from Maven Central into ENGINE_DIR/lib/ (make similarity-deps).

usage: fetch_engine.py LOCK ENGINE_DIR [--check]

Maven's own client fetches them, in one run (Debian's `maven`: mvn dependency:copy-dependencies of a
throw-away project naming exactly the lock's jars, the plugin's version pinned here), with its local
repository inside ENGINE_DIR so that nothing is written outside the build folder. Each jar is copied to a
temporary folder, its size and SHA-256 checked against the lock, then renamed into place; a jar already
there with the right hash is kept, so a second run fetches nothing. Jars the lock no longer names are
removed. ENGINE_DIR/lock is a copy of the lock written last: similarity.py
compares it with the checkout's lock and refuses a stale or partial engine. --check fetches nothing and
exits 1 naming what is missing or wrong. Exit 0 when every jar is in place.
"""
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile

# The plugin that copies artifacts out of Maven's repository, pinned like the jars themselves.
COPY_GOAL = "org.apache.maven.plugins:maven-dependency-plugin:3.6.1:copy-dependencies"


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


def fetch(entries, engine, lib):
    """Copies the jars of `entries` into `lib` in one mvn run (a JVM start is seconds), each checked first."""
    if not shutil.which("mvn"):
        sys.exit("fetch_engine: mvn is not installed (make similarity-deps installs Debian's maven)")
    with tempfile.TemporaryDirectory(dir=engine) as work:
        # A project whose dependencies are exactly the lock's jars, each without what it depends on.
        dependencies = "".join(f"<dependency><groupId>{g}</groupId><artifactId>{a}</artifactId><version>{v}</version>"
                               "<exclusions><exclusion><groupId>*</groupId><artifactId>*</artifactId></exclusion></exclusions>"
                               "</dependency>" for g, a, v, _, _ in entries)
        with open(os.path.join(work, "pom.xml"), "w", encoding="utf-8") as pom:
            pom.write('<project xmlns="http://maven.apache.org/POM/4.0.0"><modelVersion>4.0.0</modelVersion>'
                      "<groupId>t10</groupId><artifactId>jplag-engine</artifactId><version>1</version>"
                      f"<dependencies>{dependencies}</dependencies></project>")
        copied = os.path.join(work, "jars")
        command = ["mvn", "--batch-mode", "--quiet", "--file", os.path.join(work, "pom.xml"),
                   f"-Dmaven.repo.local={os.path.join(engine, 'm2')}", COPY_GOAL, f"-DoutputDirectory={copied}"]
        # Maven's run is a few seconds of JVM, mostly compiling itself: the quick compiler alone and one
        # collector thread (8.6-9.0 CPU s with the defaults, 5.1-5.8 with these; make test runs it from
        # empty beside the build). MAVEN_OPTS set by the caller wins.
        env = dict(os.environ)
        env.setdefault("MAVEN_OPTS", "-XX:TieredStopAtLevel=1 -XX:CICompilerCount=1 -XX:+UseSerialGC")
        run = subprocess.run(command, capture_output=True, text=True, errors="replace", env=env)
        said = (run.stdout + run.stderr).strip().splitlines()
        if run.returncode != 0:
            sys.exit(f"fetch_engine: mvn dependency:copy-dependencies failed (exit {run.returncode})"
                     + "".join("\n  " + line for line in said[-8:]))
        for group, artifact, version, size, sha in entries:
            name = jar_name(artifact, version)
            partial = os.path.join(copied, name)
            if not os.path.isfile(partial):
                sys.exit(f"fetch_engine: {group}:{artifact}:{version}: mvn copied no {name}")
            got_size, got_sha = os.path.getsize(partial), digest(partial)
            if got_size != size or got_sha != sha:
                sys.exit(f"fetch_engine: {group}:{artifact}:{version}: {got_size} bytes, sha256 {got_sha}; "
                         f"the lock says {size} bytes, {sha}")
        for _, artifact, version, _, _ in entries:
            os.replace(os.path.join(copied, jar_name(artifact, version)), os.path.join(lib, jar_name(artifact, version)))


def main():
    args = [a for a in sys.argv[1:] if a != "--check"]
    if len(args) != 2:
        sys.exit(__doc__.split("\n\n")[1])
    lock_path, engine = args
    # Absolute: Maven takes a relative -DoutputDirectory from the throw-away project's folder, not from here.
    engine = os.path.abspath(engine)
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
    missing = []
    for entry in entries:
        path = os.path.join(lib, jar_name(entry[1], entry[2]))
        if not (os.path.isfile(path) and os.path.getsize(path) == entry[3] and digest(path) == entry[4]):
            missing.append(entry)
            problems.append(f"{path}: missing or not the jar of the lock")
    if missing and not check:
        fetch(missing, engine, lib)
        problems = []
    if problems:
        sys.exit("\n".join(problems))
    if not check:
        shutil.copyfile(lock_path, os.path.join(engine, "lock.partial"))
        os.replace(os.path.join(engine, "lock.partial"), os.path.join(engine, "lock"))
        print(f"JPlag {entries[0][2]}: {len(entries)} jars in {lib}, each checked against {lock_path}")


if __name__ == "__main__":
    main()
