#!/usr/bin/env python3
"""Whether two screenshots (binary PPM, P6, 8-bit) show the same picture: make devcontainer-check
compares noVNC's page in Chromium with the X server's own screenshot of the desktop.

usage: same_picture.py A.ppm B.ppm MAX_FRACTION
Prints the fraction of pixels whose channels differ by more than 48 of 255 (VNC's encodings and the
browser's scaling move a value by a few steps; a different picture moves it by far more) and exits 0
only when the sizes agree and the fraction is at most MAX_FRACTION; 1 otherwise."""
import sys

import numpy


def read_ppm(path):
    with open(path, "rb") as handle:
        data = handle.read()
    fields, at = [], 0
    while len(fields) < 4:
        while data[at:at + 1].isspace():
            at += 1
        if data[at:at + 1] == b"#":
            at = data.index(b"\n", at)
            continue
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    if fields[0] != b"P6" or int(fields[3]) != 255:
        raise ValueError(f"{path}: not an 8-bit binary PPM")
    width, height = int(fields[1]), int(fields[2])
    pixels = numpy.frombuffer(data, dtype=numpy.uint8, count=width * height * 3, offset=at + 1)
    return pixels.reshape(height, width, 3)


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        a, b = read_ppm(sys.argv[1]), read_ppm(sys.argv[2])
    except (OSError, ValueError) as error:
        print(f"same_picture: {error}")
        return 1
    if a.shape != b.shape:
        print(f"same_picture: sizes differ: {a.shape[1]}x{a.shape[0]} and {b.shape[1]}x{b.shape[0]}")
        return 1
    differ = (numpy.abs(a.astype(int) - b.astype(int)) > 48).any(axis=2).mean()
    print(f"{differ * 100:.1f}% of the pixels differ by more than 48/255")
    return 0 if differ <= float(sys.argv[3]) else 1


if __name__ == "__main__":
    sys.exit(main())
