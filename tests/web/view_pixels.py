#!/usr/bin/env python3
"""The share of a screenshot's 3-D view that is not background: view_pixels.py FILE.png X0_FRACTION

Prints the fraction of the pixels right of X0_FRACTION of the width (the app's panel is on the left)
whose colour differs from the views' background (the renderer's kBackground, 0.88 0.91 0.95, by more
than 40 levels summed over RGB). Standard library only: decodes 8-bit RGB/RGBA non-interlaced PNG.
"""
import struct, sys, zlib

data = open(sys.argv[1], "rb").read()
x0f = float(sys.argv[2])
pos, idat, w = 8, b"", 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        assert depth == 8 and ctype in (2, 6) and interlace == 0, "8-bit RGB(A), not interlaced"
        bpp = 3 if ctype == 2 else 4
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
stride = w * bpp
prev = bytearray(stride)
bg = (224, 232, 242)
count = other = 0
for y in range(h):
    f = raw[y * (stride + 1)]
    line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b = prev[i]
        c = prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    prev = line
    for x in range(int(x0f * w), w, 2):
        r, g, bl = line[x * bpp:x * bpp + 3]
        count += 1
        if abs(r - bg[0]) + abs(g - bg[1]) + abs(bl - bg[2]) > 40:
            other += 1
print("%.4f" % (other / max(count, 1)))
