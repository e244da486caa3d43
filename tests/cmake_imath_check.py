#!/usr/bin/env python3
"""cmake/T10OpenEXR.cmake keeps Debian's Imath packaging notice out of a configure without hiding
warnings (issue 38). Configures two small probe projects that include the file, in OUT_DIR:
  - with the system's Imath: no "... but this file does not exist" notice (Debian 12's libimath-dev
    names libPyImath, shipped in python3-imath), while a STATUS line and a WARNING after the include
    still print;
  - with a stand-in Imath package whose Imath::Imath library is missing and which warns itself: both
    that warning and T10OpenEXR.cmake's own warning naming the missing library print.
usage: cmake_imath_check.py CMAKE SOURCE_DIR OUT_DIR
Exit 0 when both hold, 1 otherwise, 77 (skipped) where no Imath 3 CMake package is installed (OpenEXR
2.5 systems). Shown to fail on the file before the fix: the first probe printed the ten-line notice."""
import os
import shutil
import subprocess
import sys

CMAKE, SOURCE, OUT = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
INCLUDE = os.path.join(SOURCE, "cmake", "T10OpenEXR.cmake")
PROBE = f"""cmake_minimum_required(VERSION 3.16)
project(imath_probe CXX)
include("{INCLUDE}")
message(STATUS "probe: a STATUS line after the include")
message(WARNING "probe: a WARNING after the include")
"""
STAND_IN = """if(NOT TARGET Imath::Imath)
    add_library(Imath::Imath SHARED IMPORTED)
    set_target_properties(Imath::Imath PROPERTIES IMPORTED_CONFIGURATIONS NONE
                          IMPORTED_LOCATION_NONE "/nonexistent/t10-probe/libImath-3_1.so")
endif()
message(WARNING "stand-in: a warning of Imath's own package")
set(Imath_FOUND TRUE)
"""


def configure(name, extra):
    folder = os.path.join(OUT, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(folder, "CMakeLists.txt"), "w", encoding="utf-8") as f:
        f.write(PROBE)
    run = subprocess.run([CMAKE, "-S", folder, "-B", os.path.join(folder, "build")] + extra,
                         capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


failures = []
code, text = configure("system", [])
if code != 0:
    failures.append(f"the probe with the system's Imath does not configure (exit {code}):\n{text[-2000:]}")
elif "-- OpenEXR 2." in text:
    print("SKIP: OpenEXR 2.5 here, without Imath 3's CMake package")
    sys.exit(77)
else:
    if "but this file does not exist" in text:
        failures.append("the system's Imath still prints its packaging notice:\n" + text[-2000:])
    for line in ("probe: a STATUS line after the include", "probe: a WARNING after the include"):
        if line not in text:
            failures.append(f"'{line}' is missing from the configure's output")
    if not failures:
        print("ok   system Imath: no packaging notice; STATUS and WARNING after the include still print")

stand_in = os.path.join(OUT, "stand-in-imath")
os.makedirs(stand_in, exist_ok=True)
with open(os.path.join(stand_in, "ImathConfig.cmake"), "w", encoding="utf-8") as f:
    f.write(STAND_IN)
code, text = configure("stand-in", [f"-DImath_DIR={stand_in}"])
flat = " ".join(text.split())
for words in ("stand-in: a warning of Imath's own package", "/nonexistent/t10-probe/libImath-3_1.so, which does not exist",
              "probe: a WARNING after the include"):
    if words not in flat:
        failures.append(f"with an Imath whose library is missing, the configure does not say '{words}':\n{text[-2000:]}")
if not any("stand-in" in f or "missing," in f for f in failures):
    print("ok   an Imath whose library is missing: its own warning and the missing library are both reported")
for failure in failures:
    print("FAIL", failure)
sys.exit(1 if failures else 0)
