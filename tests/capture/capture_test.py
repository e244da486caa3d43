#!/usr/bin/env python3
"""The frame loop's capture hook (common/frame/include/t10/frame_observer.hpp) through its built-in
pass capture, --capture-passes DIR, which t10-grade's per-pass checks read.

usage: capture_test.py PART3 PART1 OUT_DIR   (the two stage programs)

Part 3 at 64x64 must list exactly ten passes (five horizontal + vertical pairs, steps 32-34), the
subroutines alternating horizSampleOffset / vertSampleOffset, each file 32x32 as listed, and its
last pass must be byte for byte the bloom level 1 that --dump reads after the frame (the same
texture read back the same way: no tolerance). Part 1 has no program with subroutines: an empty list
and no pass file. Without --capture-passes nothing is captured."""
import pathlib
import shutil
import subprocess
import sys

RUN = ["--headless", "--backend", "egl", "--frames", "1", "--camera", "default", "--size", "64x64"]
PASSES = 10
SUBROUTINES = ("horizSampleOffset", "vertSampleOffset")
BLOOM_LEVEL1 = "unit17_level1.pfm"  # contract::kBloomUnit, level 1


def run(program, *args):
    result = subprocess.run([program, *RUN, *args], capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        raise SystemExit(f"{program} {' '.join(args)}: exit {result.returncode}\n{result.stdout}{result.stderr}")


def check_part3(program, out, problems):
    capture, dump = out / "part3-capture", out / "part3-dump"
    run(program, "--capture-passes", str(capture), "--dump", str(dump))
    lines = (capture / "blur_passes.txt").read_text().splitlines()
    if len(lines) != PASSES:
        problems.append(f"part 3: {len(lines)} passes listed, expected {PASSES}")
    for number, line in enumerate(lines, 1):
        fields = line.split()
        if len(fields) != 5 or fields[0] != str(number):
            problems.append(f"part 3: pass line {number} is malformed: {line!r}")
            continue
        if fields[1] != SUBROUTINES[(number - 1) % 2]:
            problems.append(f"part 3: pass {number} ran {fields[1]}, expected {SUBROUTINES[(number - 1) % 2]}")
        pfm = capture / f"blur_pass{number:02d}.pfm"
        if not pfm.is_file():
            problems.append(f"part 3: {pfm} is missing")
            continue
        size = pfm.read_bytes().split(b"\n", 2)[1].decode().replace(" ", "x")
        if size != fields[4] or size != "32x32":
            problems.append(f"part 3: {pfm.name} is {size}, listed {fields[4]}, expected 32x32")
    last = capture / f"blur_pass{PASSES:02d}.pfm"
    if last.is_file() and last.read_bytes() != (dump / BLOOM_LEVEL1).read_bytes():
        problems.append(f"part 3: the last pass {last} differs from --dump's {BLOOM_LEVEL1}")


def check_part1(program, out, problems):
    capture = out / "part1-capture"
    run(program, "--capture-passes", str(capture))
    listed = (capture / "blur_passes.txt").read_text()
    files = sorted(p.name for p in capture.glob("blur_pass*.pfm"))
    if listed or files:
        problems.append(f"part 1 (no subroutines): listed {listed!r}, wrote {files}; expected nothing")


def check_off(program, out, problems):
    dump = out / "part3-off"
    run(program, "--dump", str(dump))
    if (dump / "blur_passes.txt").exists() or list(dump.glob("blur_pass*.pfm")):
        problems.append("part 3 without --capture-passes: a pass was captured")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    part3, part1, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    shutil.rmtree(out, ignore_errors=True)  # no file of an earlier run may pass for this one's
    problems = []
    check_part3(part3, out, problems)
    check_part1(part1, out, problems)
    check_off(part3, out, problems)
    for problem in problems:
        print(f"FAIL: {problem}")
    if not problems:
        print(f"ok: {PASSES} passes captured, the last one equal to --dump's bloom level 1; none without subroutines or the option")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
