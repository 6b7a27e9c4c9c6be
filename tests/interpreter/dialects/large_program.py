#!/usr/bin/env python3
"""Writes a long Fanuc or Heidenhain program for the memory measurement of the dialect
front-ends (docs/performance.md, "Dialects"): zig-zag milling moves with arcs and feed changes,
a subprogram / label called at the end (so the front-end must find it past the main flow).

    large_program.py fanuc|heidenhain LINES OUT
"""
import sys

def fanuc(lines, out):
    w = out.write
    w("%\nO1000 (LARGE)\nN10 G17 G21 G40 G49 G80 G90 G94 G54\nN20 T1 M6\nN30 G43 H1\nN40 S2000 M3\nN50 G0 X0. Y0. Z5.\nN60 G1 Z-1. F300.\n")
    n, x, y = 70, 0.0, 0.0
    for i in range(lines - 16):
        if i % 50 == 49:
            w("N%d G2 X%.3f Y%.3f R5. F%d.\n" % (n, x + 5.0, y + 5.0, 400 + i % 7 * 10))
            x, y = x + 5.0, y + 5.0
        else:
            x = (x + 1.25) % 200.0
            y = (y + 0.5 if i % 2 else y) % 150.0
            w("N%d G1 X%.3f Y%.3f\n" % (n, x, y))
        n += 10
    w("N%d M98 P2000\nN%d G0 Z50.\nN%d M30\nO2000 (SUB)\nN10 G0 X1. Y1.\nN20 M99\n%%\n" % (n, n + 10, n + 20))

def heidenhain(lines, out):
    w = out.write
    w("0 BEGIN PGM LARGE MM\n1 TOOL CALL 1 Z S2000\n2 L Z+5 R0 FMAX M3\n3 L X+0 Y+0 R0 FMAX\n4 L Z-1 R0 F300\n")
    n, x, y = 5, 0.0, 0.0
    for i in range(lines - 12):
        if i % 50 == 49:
            w("%d CC X%+.3f Y%+.3f\n" % (n, x, y + 5.0))
            n += 1
            w("%d C X%+.3f Y%+.3f DR- F%d\n" % (n, x, y + 10.0, 400 + i % 7 * 10))
            y += 10.0
        else:
            x = (x + 1.25) % 200.0
            y = (y + 0.5 if i % 2 else y) % 150.0
            w("%d L X%+.3f Y%+.3f\n" % (n, x, y))
        n += 1
    w("%d CALL LBL 1\n%d L Z+50 R0 FMAX\n%d END PGM LARGE MM\n%d LBL 1\n%d L X+1 Y+1 R0 FMAX\n%d LBL 0\n" % tuple(range(n, n + 6)))

if __name__ == "__main__":
    dialect, count, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(path, "w") as out:
        (fanuc if dialect == "fanuc" else heidenhain)(count, out)
