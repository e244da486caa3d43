#!/usr/bin/env python3
"""make bench-grader: grades a mixed class, the submissions of the grader's test batches (every
reference, shaders-only copy and rewrite of Parts 1-3, every known mistake and fitted parameter, the
broken ones: no build, shader error, crash, endless loop), with a fresh cache as a first grading of
a class would, and prints what it costs: submissions per minute, CPU seconds and peak memory per
submission.

usage: bench_grader.py T10_GRADE MAKE_SUBMISSIONS_PY SOURCE_DIR OUT_DIR JOBS
CPU time is the grader's and every process it waited for (builds, renders, FLIP); peak memory is the
largest resident set of any one of them (Linux's ru_maxrss over the children), which bounds what a
submission needs at once. Exit 1 when the grader fails."""
import os
import resource
import shutil
import subprocess
import sys
import time

GRADER, MAKE_SUBMISSIONS, SOURCE, OUT, JOBS = sys.argv[1:6]
TIMEOUT = "20"  # as the test batches: the endless loop is killed after 20 s

shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
submissions = os.path.join(OUT, "submissions")
subprocess.run([sys.executable, MAKE_SUBMISSIONS, SOURCE, submissions], check=True, stdout=subprocess.DEVNULL)

rows = []
total = {"count": 0, "wall": 0.0, "cpu": 0.0, "peak": 0}
for part in (1, 2, 3):
    folder = os.path.join(submissions, f"part{part}")
    names = sorted(os.listdir(folder))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    run = subprocess.run([GRADER, "--part", str(part), "--jobs", JOBS, "--timeout", TIMEOUT, "--fill-from-reference", "all",
                          "--cache", os.path.join(OUT, "cache"), "--report", os.path.join(OUT, f"reports-part{part}")]
                         + [os.path.join(folder, n) for n in names], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        sys.exit(f"bench_grader.py: t10-grade --part {part} exit {run.returncode}:\n{run.stderr[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    rows.append((f"Part {part}", len(names), wall, cpu, after.ru_maxrss))
    total["count"] += len(names)
    total["wall"] += wall
    total["cpu"] += cpu
    total["peak"] = max(total["peak"], after.ru_maxrss)

print(f"t10-grade, --jobs {JOBS}, {os.cpu_count()} CPUs, a fresh cache (reference renders and builds included)")
print(f"{'batch':8} {'subs':>5} {'wall s':>8} {'subs/min':>9} {'CPU s/sub':>10} {'peak MiB':>9}")
for label, count, wall, cpu, peak in rows + [("all", total["count"], total["wall"], total["cpu"], total["peak"])]:
    print(f"{label:8} {count:5d} {wall:8.1f} {60 * count / wall:9.1f} {cpu / count:10.2f} {peak / 1024:9.0f}")
