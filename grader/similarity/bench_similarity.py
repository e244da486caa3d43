#!/usr/bin/env python3
"""What --similarity costs for a big class (make bench-similarity): 900 generated Part 3 submissions.

usage: bench_similarity.py SOURCE_ROOT ENGINE_DIR OUT_DIR [STUDENTS]

Writes the class with grader/tests/similarity/make_class.py (not timed: two planted pairs among honest
students with independent edits), then times similarity.py over it: wall time, CPU time (user + system
of similarity.py and JPlag's JVM) and the peak memory of the largest process (the JVM). The target is
two minutes of wall time on two cores; on a shared machine the load average is printed beside it, and
CPU time / cores is what an idle machine would take at best. Exits 0 once the report is written (a
shared machine's wall time is no verdict on the code); the line says when the wall time was over.
"""
import json
import os
import resource
import subprocess
import sys
import time


def main():
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        return 2
    root, engine, out = sys.argv[1:4]
    students = int(sys.argv[4]) if len(sys.argv) == 5 else 900
    folder = os.path.join(out, "class")
    subprocess.run([sys.executable, os.path.join(root, "grader", "tests", "similarity", "make_class.py"), root, folder,
                    "--honest", str(students - 9), "--seed", "7"], check=True, stdout=subprocess.DEVNULL)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    report = os.path.join(out, "report")
    subprocess.run([sys.executable, os.path.join(root, "grader", "similarity", "similarity.py"), "--part", "3", "--report",
                    report, "--engine", engine, "--folder", folder], check=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(report, "similarity.json"), encoding="utf-8") as f:
        pairs = json.load(f)["pairs"]
    cores = os.cpu_count() or 1
    n = students
    print(f"bench-similarity: {n} submissions ({n * (n - 1) // 2} pairs per language, host code and shaders): "
          f"{wall:.1f} s wall (target 120 s on 2 cores), {cpu:.1f} s CPU ({cpu / cores:.1f} s on {cores} idle cores), "
          f"peak memory {after.ru_maxrss / 1024:.0f} MiB (the largest process); load average "
          f"{os.getloadavg()[0]:.1f}; {sum(p['flagged'] for p in pairs)} pairs to review, {len(pairs)} pairs share anything")
    if wall > 120:
        print(f"bench-similarity: over the 120 s target in wall time ({wall:.0f} s) with a load average of "
              f"{os.getloadavg()[0]:.1f}; the CPU time says what two idle cores would take")
    return 0


if __name__ == "__main__":
    sys.exit(main())
