#!/usr/bin/env python3
"""Labels drawn with a glyph the font lacks (issue 25.4: the diameter sign U+2300 came out
as an empty box in every PNG and PDF). Two readings of the same drawings:

  glyphs.py sheet FILE.svg...          a page cairo wrote as SVG (the build sheet): text is
      drawn as glyph outlines, one <symbol> per glyph of each font subset, and each subset's
      glyph 0 is the font's .notdef (the box). A <use> of a glyph whose outline is its
      subset's .notdef is a character the font lacks.
  glyphs.py labels FONT FILE.svg...    the section drawing's SVG (<text> labels): every
      character of every label is in the charset of FONT (the font file fontconfig gives
      cairo for "sans-serif", read with fc-query).

Prints one line per missing glyph; exit 1 if any."""
import html
import re
import subprocess
import sys


def sheet(paths):
    bad = 0
    for p in paths:
        s = open(p, encoding="utf-8").read()
        sym = dict(re.findall(r'<symbol overflow="visible" id="(glyph\d+-\d+)">\s*(.*?)</symbol>', s, re.S))
        if not sym:
            print(f"{p}: no glyphs (not a cairo SVG page?)")
            bad += 1
        used = set(re.findall(r'href="#(glyph\d+-\d+)"', s))
        for g in sorted(used):
            sub = g.split("-")[0]
            if g == sub + "-0" or sym.get(g) == sym.get(sub + "-0"):
                print(f"{p}: {g} is drawn as the font's .notdef (a character the font lacks)")
                bad += 1
    return bad


def charset(font):
    out = subprocess.run(["fc-query", "-f", "%{charset}", font], capture_output=True,
                         text=True, check=True).stdout
    have = set()
    for r in out.split():
        a, _, b = r.partition("-")
        have.update(range(int(a, 16), int(b or a, 16) + 1))
    return have


def labels(font, paths):
    have, bad = charset(font), 0
    for p in paths:
        s = open(p, encoding="utf-8").read()
        texts = [html.unescape(t) for t in re.findall(r"<text[^>]*>([^<]*)</text>", s)]
        if not texts:
            print(f"{p}: no labels")
            bad += 1
        for t in texts:
            for ch in sorted(set(t)):
                if ord(ch) not in have and not ch.isspace():
                    print(f"{p}: '{t}' has U+{ord(ch):04X} ({ch}), not in {font}")
                    bad += 1
    return bad


if __name__ == "__main__":
    if sys.argv[1] == "sheet":
        sys.exit(1 if sheet(sys.argv[2:]) else 0)
    sys.exit(1 if labels(sys.argv[2], sys.argv[3:]) else 0)
