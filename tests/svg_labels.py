#!/usr/bin/env python3
"""Labels of a section drawing (SVG) that overlap: each <text> is boxed as the
drawing's own layout sizes it (0.58 em per character, the mean advance of
DejaVu Sans; 0.75 em above the baseline, 0.2 em below); rotated text (the travel
bracket's) is skipped. Prints one line per overlapping pair; exit 1 if any.
Usage: svg_labels.py FILE.svg..."""
import html
import re
import sys


def boxes(path):
    s = open(path, encoding="utf-8").read()
    out = []
    for m in re.finditer(r"<text([^>]*)>([^<]*)</text>", s):
        a, t = m.group(1), html.unescape(m.group(2))
        if "rotate(" in a:
            continue
        g = lambda k: re.search(k + r'="([^"]*)"', a).group(1)
        x, y, fs, anc = float(g("x")), float(g("y")), float(g("font-size")), g("text-anchor")
        w = 0.58 * fs * len(t)
        x0 = x if anc == "start" else x - w / 2 if anc == "middle" else x - w
        out.append((x0, y - 0.75 * fs, x0 + w, y + 0.2 * fs, t))
    return out


bad = 0
for p in sys.argv[1:]:
    b = boxes(p)
    if not b:
        print(f"{p}: no labels")
        bad += 1
    for i in range(len(b)):
        for j in range(i + 1, len(b)):
            A, B = b[i], b[j]
            if A[0] < B[2] and B[0] < A[2] and A[1] < B[3] and B[1] < A[3]:
                print(f"{p}: '{A[4]}' overlaps '{B[4]}'")
                bad += 1
sys.exit(1 if bad else 0)
