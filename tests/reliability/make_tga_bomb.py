#!/usr/bin/env python3
"""Writes an RLE TGA "bomb": the header declares 16384 x 16384 RGBA (1 GiB decoded), and the file
holds just enough bytes (10.5 MB) to pass the loader's smallest-possible-stream check, as run
packets of ONE pixel each: it can only ever decode 2.1 million of its 268 million pixels, so it is
truncated from the first packet on. usage: make_tga_bomb.py OUT.tga"""
import struct
import sys

SIDE = 16384
BPP = 4
pixels = SIDE * SIDE
minimum = (pixels + 127) // 128 * (1 + BPP)  # what the loader requires before decoding
header = struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, SIDE, SIDE, 32, 0x20)
packet = bytes([0x80, 10, 20, 30, 255])  # a run packet of one pixel
with open(sys.argv[1], "wb") as out:
    out.write(header)
    out.write(packet * (minimum // len(packet) + 1))
