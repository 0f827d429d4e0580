#!/usr/bin/env bash
# The section drawing a maker measures against (issue 25.4): the setting's
# depth below the rim is dimensioned (its value is the sheet's depth_set_mm,
# computed there from the rim and the weight's end), and tippe build
# --one-to-one writes the section's PDF on an A4 landscape page at 1:1: the
# check bar and the sphere's outline measure 50 mm in PDF points (1/72 in).
# Usage: test_drawing_one_to_one.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

for stem in m12-setscrew drilled-ball-best shell-rod-iron; do
    "$tippe" build designs/$stem.json -o "$tmp/$stem" --json >"$tmp/$stem.json" 2>/dev/null
    # the drawing shows the flips setting, else the first reachable one
    python3 - "$tmp/$stem.json" "$tmp/$stem/$stem-section.svg" <<'PY' && ok || bad "$stem: the section's depth is not the sheet's"
import json, re, sys
o = json.load(open(sys.argv[1]))
s = o["settings"]
shown = 1 if s[1]["reachable"] else [k for k in range(3) if s[k]["reachable"]][0]
svg = open(sys.argv[2]).read()
m = re.search(r'data-name="setting.depth_mm" data-mm="([-0-9.e]+)"', svg)
assert m, "no depth dimension"
# the drawing's value is |rim - end| of the drawn setting; the sheet's is its
# signed depth: equal to the 1e-9 of the %.10g the SVG writes
assert abs(float(m.group(1)) - abs(s[shown]["depth_set_mm"])) < 1e-6, (m.group(1), s[shown]["depth_set_mm"])
PY
done

"$tippe" build designs/m12-setscrew.json -o "$tmp/one" --one-to-one >/dev/null 2>&1
check "--one-to-one: the section PDF is written" test -s "$tmp/one/m12-setscrew-section.pdf"
python3 - "$tmp/one/m12-setscrew-section.pdf" <<'PY' && ok || bad "--one-to-one: the PDF is not A4 at 1:1"
import re, sys, zlib
d = open(sys.argv[1], "rb").read()
box = [float(x) for x in re.search(rb"/MediaBox \[ *([-0-9. ]+)\]", d).group(1).split()]
assert abs(box[2] - 841.89) < 0.01 and abs(box[3] - 595.28) < 0.01, box   # A4 landscape, pt
MM = 72 / 25.4  # PDF points per mm
bar, ball = [], []
for m in re.finditer(rb"stream\r?\n(.*?)endstream", d, re.S):
    try:
        t = zlib.decompress(m.group(1)).decode("latin1")
    except Exception:
        continue
    for a, b, c, e in re.findall(r"(-?[\d.]+) (-?[\d.]+) m (-?[\d.]+) (-?[\d.]+) l S", t):
        a, b, c, e = map(float, (a, b, c, e))
        if abs(b - e) < 1e-3:
            bar.append(abs(c - a) / MM)
    # the printed body's fill (ABSplus, the first material's colour): every
    # outline point of it
    for path in re.findall(r"0\.78 0\.87 0\.97 rg (.*?) f", t, re.S):
        ball += [float(x) for x in re.findall(r"(-?[\d.]+) -?[\d.]+ [ml]", path)]
# the bar: 50 mm to the 0.001 pt cairo writes; the outline: 2R = 50 mm to the
# polygon's chord error and the pt rounding, 0.02 mm
assert any(abs(b - 50) < 0.005 for b in bar), bar
assert abs((max(ball) - min(ball)) / MM - 50) < 0.02, (max(ball) - min(ball)) / MM
PY

"$tippe" build designs/m12-setscrew.json -o "$tmp/no" --one-to-one --no-export >/dev/null 2>"$tmp/no.err"
check "--one-to-one with --no-export: refused with exit 2" test $? -eq 2
check "... naming both options" grep -q -- "--one-to-one.*--no-export" "$tmp/no.err"

# a top of radius 200 mm cannot be drawn at 1:1 on A4: refused, saying why
"$tippe" build designs/m12-setscrew.json --set radius_mm=200 -o "$tmp/big" --one-to-one >/dev/null 2>"$tmp/big.err"
check "a 400 mm ball at 1:1: refused with exit 2" test $? -eq 2
check "... saying it is larger than an A4 page" grep -q "larger than an A4 landscape page" "$tmp/big.err"
finish
