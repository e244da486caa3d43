#!/usr/bin/env python3
"""The grader's builds use the precompiled t10/app.hpp (grader/CMakeLists.txt, compile/build.cpp).

usage: precompiled_check.py HOST_KIT SOURCE_DIR CACHE_BUILDS
1. The kit's own compile of Part 3's Tutorial10.cpp (its compiler, flags, include folders and
   definitions, the header's folder first, as build.cpp calls it) takes the .gch: GCC's -H output
   starts with "! .../t10/app.hpp.gch", and -Winvalid-pch prints nothing.
2. Every build in CACHE_BUILDS (the grader's cache, after the Part 3 batch) made since the header was searched the header's
   folder inside its sandbox (build.sh) and its log has no -Winvalid-pch warning: there a .gch that
   does not fit the call would say "not used because ...".
Without them every build parses common/'s headers again (0.8 s of CPU instead of 0.1): the same
programs, only slower, which no other test would notice. Exit 1 naming what failed."""
import os
import subprocess
import sys

kit_file, source, cache_builds = sys.argv[1:4]
kit = {}
with open(kit_file, encoding="utf-8") as f:
    for line in f:
        key, _, value = line.rstrip("\n").partition(" ")
        kit[key] = value
failures = []
pch_dir = kit.get("pch", "")
gch = os.path.join(pch_dir, "t10", "app.hpp.gch")
if not pch_dir or not os.path.isfile(gch):
    sys.exit(f"precompiled_check.py: {kit_file} names no precompiled header (pch line: {pch_dir!r}, {gch} missing)")

split = lambda v: [x for x in v.split(";") if x]
# The compile flags only (the kit's -Wl and -fuse-ld flags are the link's).
flags = [f for f in split(kit["flags"]) if not f.startswith("-Wl,") and not f.startswith("-fuse-ld")]
argv = ([kit["compiler"]] + flags + ["-Winvalid-pch", "-I" + pch_dir] + ["-I" + i for i in split(kit["includes"])] +
        ["-D" + d for d in split(kit["defines"])] +
        ['-DT10_STAGE_NAME="tutorial10_part3_gaussian"', '-DT10_STAGE_SHADER_DIR="/submission"', "-fsyntax-only", "-H",
         os.path.join(source, "tutorial10_part3_gaussian", "Tutorial10.cpp")])
run = subprocess.run(argv, capture_output=True, text=True)
lines = run.stderr.splitlines()
if run.returncode != 0:
    failures.append(f"the kit's compile of Part 3 failed ({run.returncode}): {run.stderr[-1500:]}")
elif not lines or not lines[0].startswith("! ") or not lines[0].endswith("t10/app.hpp.gch"):
    first = lines[0] if lines else "(nothing)"
    failures.append(f"the kit's compile of Part 3 did not take {gch}: -H printed first {first!r}")
invalid = [l for l in lines if "Winvalid-pch" in l or "not used because" in l]
if invalid:
    failures.append("the kit's compile: " + "; ".join(invalid[:3]))

builds = sorted(os.listdir(cache_builds)) if os.path.isdir(cache_builds) else []
checked = 0
for name in builds:
    script, log = (os.path.join(cache_builds, name, f) for f in ("build.sh", "build.log"))
    # Only builds made since the header was (a long-used build folder keeps older ones).
    if not os.path.isfile(script) or os.path.getmtime(script) < os.path.getmtime(gch):
        continue
    checked += 1
    with open(script, encoding="utf-8", errors="replace") as f:
        if "'-I/t10/pch'" not in f.read():
            failures.append(f"{script}: the build did not search /t10/pch")
    with open(log, encoding="utf-8", errors="replace") as f:
        text = f.read()
    if "Winvalid-pch" in text or "not used because" in text:
        failures.append(f"{log}: {text.strip()[:300]}")
if checked == 0:
    failures.append(f"{cache_builds}: no builds made since {gch} to check (run after the Part 3 batch)")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"the kit's compile takes {gch}; {checked} cached builds searched /t10/pch with no -Winvalid-pch warning")
