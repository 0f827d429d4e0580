#!/usr/bin/env bash
# The slicer in the loop (docs/slicer-measurements.md): tools/slice.sh exports a printed design
# and slices it headless with the shipped profile; PrusaSlicer applies the 3MF's per-object
# settings (0.2 mm layers, the design's infill); tools/gcode_check.py accounts for every
# millimetre of filament the slicer says it uses (body plus skirt), and puts the M12 body where
# the design has it (centre of mass at the sphere's centre, on the axis). Without PrusaSlicer
# slice.sh names the package to install. Skipped (with a line saying so) when prusa-slicer is
# not on PATH; CI installs it (tools/deps.sh).
# Usage: test_slicer.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
tippe_abs="$(cd "$(dirname "$tippe")" && pwd)/$(basename "$tippe")"

# without the slicer: exit 3 and a message naming the Debian package
if PRUSA_SLICER=/nonexistent/prusa-slicer TIPPE="$tippe_abs" tools/slice.sh \
        designs/m12-setscrew-printed.json "$tmp/none" >/dev/null 2>"$tmp/none.err"; then
    bad "slice.sh succeeded without a slicer"
else
    rc=$?
    [ $rc -eq 3 ] && ok || bad "slice.sh without a slicer: exit $rc, want 3"
    grep -q "Debian package prusa-slicer" "$tmp/none.err" && ok ||
        bad "slice.sh without a slicer does not name the package: $(cat "$tmp/none.err")"
fi

# gcode_check.py on a G-code written by hand: a ring of radius 10 mm at z 0.2 (E absolute, with a
# retraction, a G92 reset and a travel), the same ring at z 0.4 (E relative), and a skirt that is
# not body. Each ring: 4 chords of a square inscribed in the circle, 1 mm of filament per mm.
"$py" - "$tmp/hand.gcode" <<'EOF'
import math, sys
r = 10.0
pts = [(r * math.cos(k * math.pi / 2), r * math.sin(k * math.pi / 2)) for k in range(5)]
side = math.dist(pts[0], pts[1])
g = ["; filament_diameter = 1.75 placeholder", "G90", "M82", "G92 E0", "G1 Z0.2", ";TYPE:External perimeter",
     ";HEIGHT:0.2", ";WIDTH:0.45", "G1 X%.6f Y%.6f" % pts[0]]
e = 0.0
for k in range(1, 5):
    e += side
    g.append("G1 X%.6f Y%.6f E%.6f" % (pts[k] + (e,)))
    if k == 2:  # retract, travel back and forth, reset E, unretract
        g += ["G1 E%.6f" % (e - 0.8), "G1 X0 Y0", "G1 X%.6f Y%.6f" % pts[k], "G92 E0", "G1 E0.8"]
        e = 0.8
g += ["M83", "G1 Z0.4", "G1 X%.6f Y%.6f" % pts[0]]
for k in range(1, 5):
    g.append("G1 X%.6f Y%.6f E%.6f" % (pts[k] + (side,)))
g += [";TYPE:Skirt/Brim", "G1 X30 Y0", "G1 X40 Y0 E5", "; filament_diameter = 1.75"]
open(sys.argv[1], "w").write("\n".join(g) + "\n")
EOF
"$py" tools/gcode_check.py "$tmp/hand.gcode" --density 1 --axis-xy 0 0 --json > "$tmp/hand.json" 2>"$tmp/hand.err" &&
"$py" - "$tmp/hand.json" <<'EOF' && ok || bad "gcode_check on a hand-written G-code: $(cat "$tmp/hand.err")"
import json, math, sys
c = json.load(open(sys.argv[1]))
a = math.pi * 1.75 ** 2 / 4
side = 10 * math.sqrt(2)
V = 8 * side * a
assert abs(c["body_volume_mm3"] - V) < 1e-6 * V, (c["body_volume_mm3"], V)
assert abs(c["by_type"]["Skirt/Brim"]["volume_mm3"] - 5 * a) < 1e-6
assert c["by_type"]["Skirt/Brim"]["body"] is False
# half the volume at z 0.1 (the bead's middle), half at 0.3
assert abs(c["com_z_mm"] - 0.2) < 1e-6, c["com_z_mm"]
# C of a chord at distance d = r / sqrt(2) from the centre, length L: per unit mass d^2 + L^2 / 12,
# plus the bead's width across it, w^2 / 12
mC = (10 ** 2 / 2 + side ** 2 / 12 + 0.45 ** 2 / 12) * V / 1000
assert abs(c["C_g_mm2"] - mC) < 1e-6 * mC, (c["C_g_mm2"], mC)
# A: half of C's in-plane part, plus the z spread (0.1 mm either side) and the bead height h^2 / 12
mA = mC / 2 + (0.1 ** 2 + 0.2 ** 2 / 12) * V / 1000
assert abs(c["A_g_mm2"] - mA) < 1e-6 * mA, (c["A_g_mm2"], mA)
EOF

if ! command -v prusa-slicer >/dev/null; then
    echo "$test_name: prusa-slicer not on PATH: the slicing checks are skipped"
    finish
    exit $?
fi

zb=-24.382998  # the M12 body's lowest point at --clearance-mm 0 (tippe export --json)
for f in 0.15 0.4; do
    out="$tmp/m12-$f"
    check "slice.sh m12 at infill $f" env TIPPE="$tippe_abs" tools/slice.sh \
        designs/m12-setscrew-printed.json "$out" --set "parts.body.print.infill=$f" \
        -- --clearance-mm 0 >/dev/null || continue
    g="$out/m12-setscrew-printed.gcode"
    # the 3MF carries the infill the design asks for, as PrusaSlicer reads it
    "$py" - "$out/m12-setscrew-printed.3mf" "$f" <<'EOF' && ok || bad "3MF fill_density for infill $f"
import sys, zipfile
cfg = zipfile.ZipFile(sys.argv[1]).read("Metadata/Slic3r_PE_model.config").decode()
want = '%g%%' % (100 * float(sys.argv[2]))
assert 'key="fill_density" value="%s"' % want in cfg, cfg
EOF
    check "gcode_check on $g" sh -c "'$py' tools/gcode_check.py '$g' --density 1.08 --z-bottom-mm $zb --json > '$out/check.json'" || continue
    "$py" - "$out/check.json" "$g" "$f" <<'EOF' && ok || bad "G-code body of m12 at infill $f"
import json, sys
c = json.load(open(sys.argv[1]))
lines = open(sys.argv[2]).read().splitlines()
# every extrusion is counted: body + skirt = the slicer's own filament total (2 decimals of cm^3)
total = sum(t["volume_mm3"] for t in c["by_type"].values()) / 1000
said = float(c["slicer_filament_cm3"])
assert abs(total - said) <= 0.006 + 1e-4 * said, (total, said)
# the per-object layer height (0.2 mm, from the 3MF) is applied: 48.77 mm in 0.2 mm layers
assert 240 <= c["layer_count"] <= 246, c["layer_count"]
# the body sits where the design has it: centre of mass at the centre, on the axis
assert abs(c["com_z_mm"]) < 0.15, c["com_z_mm"]
assert max(abs(x) for x in c["com_xy_offset_mm"]) < 0.2, c["com_xy_offset_mm"]
# a body of revolution: A about x and about y agree
assert abs(c["A_x_g_mm2"] - c["A_y_g_mm2"]) < 0.005 * c["A_g_mm2"]
# the mass as measured when this test was written (docs/slicer-measurements.md), +-3 %
want = {"0.15": 17.93, "0.4": 31.40}[sys.argv[3]]
assert abs(c["body_mass_g"] - want) < 0.03 * want, (c["body_mass_g"], want)
EOF
done
# supports (issue 37): the M12 printed whole wants them under its lower hemisphere, and the 3MF
# turns them on for it, from the build plate only. The reader leaves their lines out of the
# part: the body's mass equals the same 3MF's sliced with supports off within 0.3 % (the lines
# over the support's interface, 0.2 mm below them, are laid as over air: the body's lines are
# the slicer's either way; measured 0.000 g of 17.93 g), and tippe eval says what they weighed
# A G-code whose hole is printed otherwise than the model's (slice.sh's export at --clearance-mm
# 0: the hole at 11 mm) read into the part as made (the hole at the 10.25 mm tap drill, whose
# rim lies sqrt(25^2 - 5.125^2) - sqrt(25^2 - 5.5^2) = 0.0815 mm nearer the poles) stands where
# its own hole opens: the same top, to the G-code's measured hole (its polygon's sag, a few
# hundredths of a mm in radius, ~0.01 mm at the rim), as the design given the G-code's hole
out="$tmp/m12-0.15"
if [ -f "$out/m12-setscrew-printed.gcode" ]; then
    for v in made written; do
        set=()
        [ $v = written ] && set=(--set parts.hole.printed_radius_mm=5.5)
        "$tippe" eval designs/m12-setscrew-printed.json --z2 5 --json "${set[@]}" \
            --set "parts.body.print.gcode=$out/m12-setscrew-printed.gcode" >"$tmp/bed-$v.json"
    done
    "$py" - "$tmp/bed-made.json" "$tmp/bed-written.json" <<'EOF' && ok || bad "a G-code with another hole placed by its own hole"
import json, re, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert a["mass_kg"] == b["mass_kg"], (a["mass_kg"], b["mass_kg"])
# placed by the model's bed it stood 0.08 mm off (eps 0.050 mm off); by its hole within 0.01 mm
assert abs(a["eps_m"] - b["eps_m"]) < 1e-5, (a["eps_m"], b["eps_m"])
note = [q for q in a["printed_parts"] if q["model"] == "gcode"][0]["gcode_note"]
shift = float(re.search(r"its bed is where its own holes open, ([0-9.]+) mm above", note).group(1))
assert abs(shift - 0.0815) < 0.01, note
assert not [q for q in b["printed_parts"] if q["model"] == "gcode"][0]["gcode_note"]
EOF
fi
# a design's filament diameter wins over the G-code's header, and says so: PrusaSlicer's
# header gives 1.75 mm; read at 2.85 mm every bead holds (2.85/1.75)^2 = 2.652 times the
# plastic, +165.2 % (the note's one decimal); at the header's own diameter no note
if [ -f "$out/m12-setscrew-printed.gcode" ]; then
    for dmm in 2.85 1.75; do
        "$tippe" eval designs/m12-setscrew-printed.json --z2 5 --json \
            --set "parts.body.print.gcode=$out/m12-setscrew-printed.gcode" \
            --set parts.body.print.filament_diameter_mm=$dmm >"$tmp/diam-$dmm.json"
    done
    "$py" - "$tmp/diam-2.85.json" "$tmp/diam-1.75.json" <<'EOF' && ok || bad "a filament diameter against the G-code's header is said"
import json, sys
a, b = ([q for q in json.load(open(f))["printed_parts"] if q["model"] == "gcode"][0] for f in sys.argv[1:3])
assert "where its header says 1.75 mm: +165.2 %" in a["gcode_note"], a["gcode_note"]
assert "header says" not in b["gcode_note"], b["gcode_note"]
EOF
fi
out="$tmp/m12-0.15"
if [ -f "$out/m12-setscrew-printed.gcode" ]; then
    nosup="$tmp/nosup"
    mkdir -p "$nosup"
    "$py" - "$out/m12-setscrew-printed.3mf" "$nosup/m12.3mf" <<'EOF' && ok || bad "the 3MF turns supports on for the whole ball"
import sys, zipfile
src, dst = sys.argv[1:3]
zin = zipfile.ZipFile(src)
cfg = zin.read("Metadata/Slic3r_PE_model.config").decode()
for k in ('key="support_material" value="1"', 'key="support_material_auto" value="1"',
          'key="support_material_buildplate_only" value="1"'):
    assert k in cfg, (k, cfg)
with zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zout:
    for i in zin.infolist():
        data = zin.read(i.filename)
        if i.filename == "Metadata/Slic3r_PE_model.config":
            data = cfg.replace('key="support_material" value="1"',
                               'key="support_material" value="0"').encode()
        zout.writestr(i, data)
EOF
    if prusa-slicer --export-gcode --load designs/slicer/prusa-pla-0.4mm.ini -o "$nosup/m12.gcode"             "$nosup/m12.3mf" >"$nosup/log" 2>&1; then
        for v in with:"$out/m12-setscrew-printed.gcode" without:"$nosup/m12.gcode"; do
            "$tippe" eval designs/m12-setscrew-printed.json --z2 5 --json \
                --set "parts.body.print.gcode=${v#*:}" >"$tmp/sup-${v%%:*}.json" 2>>"$nosup/log"
        done
        "$py" - "$tmp/sup-with.json" "$tmp/sup-without.json" <<'EOF' && ok || bad "supports left out of the body: $(tail -3 "$nosup/log")"
import json, sys
a, b = ([q for q in json.load(open(f))["printed_parts"] if q["model"] == "gcode"][0]
        for f in sys.argv[1:3])
assert abs(a["printed_mass_kg"] / b["printed_mass_kg"] - 1) < 0.003, (a, b)
assert abs(a["body_A_over_C"] - b["body_A_over_C"]) < 0.001, (a, b)
# about 3 cm^3 of support under a 50 mm ball (docs/printing.md, "Supports"): 1 .. 6 g at 1.08
assert 1e-3 < a["gcode_support_mass_kg"] < 6e-3 and b["gcode_support_mass_kg"] == 0, (a, b)
EOF
    else
        bad "prusa-slicer without supports: $(tail -3 "$nosup/log")"
    fi
fi
# tippe slice: the printed M12 sliced with the shipped profile, its G-code read back as the
# part. The print model beside it (docs/printing.md, "The print model against the slicer"):
# the body's mass within 2 % at 15, 40 and 100 % (the issue's goal; measured +1.8, +1.2 and
# +0.4 %), its A/C within 0.008 (measured -0.0063 at 15 %, -0.0043 at 40 %, -0.0008 at 100 %:
# the anchors' band the model puts along the boundaries, where the slicer lays 20 % less).
for f in 0.15 0.4 1; do
    out="$tmp/slice-$f"
    "$tippe" slice designs/m12-setscrew-printed.json -o "$out" --set "parts.body.print.infill=$f" \
        --json >"$out.json" 2>"$out.err" || { bad "tippe slice at $f: $(tail -2 "$out.err")"; continue; }
    "$py" - "$out.json" <<'EOF' && ok || bad "tippe slice at infill $f: model against G-code"
import json, sys
o = json.load(open(sys.argv[1]))
p = o["sliced_parts"]["printed_parts"][0]
assert p["model"] == "gcode" and p["gcode_generator"].startswith("PrusaSlicer"), p
g, m = p["printed_mass_kg"], p["model_mass_kg"]
assert abs(m / g - 1) < 0.02, (m, g)
assert abs(p["model_body_A_over_C"] - p["body_A_over_C"]) < 0.008, p
# the build sheet's verdict for both bodies, with each behaviour's robust width
words = ("3-in-1 and settable", "3-in-1 on paper only", "not 3-in-1")
for side in ("sliced", "model"):
    v = o["verdict"][side]
    assert v["verdict"] in words, v
    assert v["settable"] == (v["verdict"] == words[0]), v
    w = [x for x in v["robust_width_mm"].values() if x is not None]
    assert all(x >= 0 for x in w) and v["min_setting_mm"] > 0, v
# printed at 15 % the M12 hangs at every Z2, by the G-code as by the model (docs/printing.md)
if abs(p["slicer_infill"] - 0.15) < 1e-9:
    assert o["verdict"]["sliced"]["verdict"] == o["verdict"]["model"]["verdict"] == words[2], o["verdict"]
EOF
done
# the text report ends with the verdicts (the shipped design: 15 %, not 3-in-1 either way)
"$tippe" slice designs/m12-setscrew-printed.json -o "$tmp/slice-text" >"$tmp/slice-text.out" 2>/dev/null &&
    grep -q "^verdict  G-code: not 3-in-1" "$tmp/slice-text.out" &&
    grep -q "^         model:  not 3-in-1" "$tmp/slice-text.out" && ok ||
    bad "tippe slice's text does not end with the verdicts: $(tail -4 "$tmp/slice-text.out")"
# the part as used (issue 40): the hole printed at the M12's tap drill (fit tap, as tippe build's
# 3MF has it) and then tapped; the G-code's plastic inside the design's 11 mm is cut from its
# body, and the report says the G-code's hole is narrower than the design's
out="$tmp/tap"
if env TIPPE="$tippe_abs" tools/slice.sh designs/m12-setscrew-printed.json "$out" \
        --set parts.body.print.infill=0.5 --set parts.hole.fit=tap >/dev/null 2>"$out.err"; then
    "$tippe" eval designs/m12-setscrew-printed.json --z2 5 --json --set parts.body.print.infill=0.5 \
        --set "parts.body.print.gcode=$out/m12-setscrew-printed.gcode" >"$out.json" 2>>"$out.err" &&
    "$py" - "$out.json" <<'EOF' && ok || bad "the tapped hole cut from the G-code: $(tail -3 "$out.err")"
import json, sys
p = [q for q in json.load(open(sys.argv[1]))["printed_parts"] if q["model"] == "gcode"][0]
# the G-code's hole is the tap drill's 10.25 mm (a bead's edge within 0.1 mm), the design's 11 mm
assert "is 10.2" in p["gcode_note"] and "the design's 11.00 mm" in p["gcode_note"], p["gcode_note"]
# the ring between 10.25 and 11 mm over the hole's 49 mm: pi (5.5^2 - 5.125^2) 49 mm^3 of
# solid walls, 0.68 g at 1.08 g/cm^3; the beads' rounded edges leave a little less
assert 0.5e-3 < p["gcode_cut_mass_kg"] < 0.7e-3, p["gcode_cut_mass_kg"]
EOF
    # the part as made: the model with the hole printed where the G-code has it and tapped after
    # (printed_radius_mm, as tippe build and tippe slice model it) against the same G-code
    "$tippe" eval designs/m12-setscrew-printed.json --z2 5 --json --set parts.body.print.infill=0.5 \
        --set parts.hole.printed_radius_mm=5.125 \
        --set "parts.body.print.gcode=$out/m12-setscrew-printed.gcode" >"$out-made.json" 2>>"$out.err" &&
    "$py" - "$out-made.json" <<'EOF' && ok || bad "the part as made against its G-code: $(tail -3 "$out.err")"
import json, sys
p = [q for q in json.load(open(sys.argv[1]))["printed_parts"] if q["model"] == "gcode"][0]
assert "printed 10.25 mm across" in p["gcode_note"], p["gcode_note"]
# mass within 2.5 %: the print model's own error against the slicer at 50 % infill with the hole
# printed where the model has it (+1.9 %, docs/printing.md) and the cut's (0.624 g against the
# G-code's 0.649 g, 0.07 %); measured +1.9 % (before the part as made: +2.9 %). Body A/C within
# 0.005, the issue's bound (measured -0.0014; before: +0.0040)
assert abs(p["model_mass_kg"] / p["printed_mass_kg"] - 1) < 0.025, p
assert abs(p["model_body_A_over_C"] - p["body_A_over_C"]) < 0.005, p
EOF
else
    bad "slice.sh with the hole at the tap drill: $(tail -3 "$out.err")"
fi
# tippe slice prints the hole as tippe build does (the tap drill) and models the part as made:
# at 50 % the model (tippe build's verdict) and the G-code give the same verdict (issue 40)
"$tippe" slice designs/m12-setscrew-printed.json -o "$tmp/slice-made" --json \
    --set parts.body.print.infill=0.5 >"$tmp/slice-made.json" 2>"$tmp/slice-made.err" &&
"$py" - "$tmp/slice-made.json" <<'EOF' && ok || bad "tippe slice at 50 %: the part as made: $(tail -3 "$tmp/slice-made.err")"
import json, sys
o = json.load(open(sys.argv[1]))
p = o["sliced_parts"]["printed_parts"][0]
assert "is 10.2" in p["gcode_note"] and "printed 10.25 mm across" in p["gcode_note"], p
v = o["verdict"]
assert v["sliced"]["verdict"] == v["model"]["verdict"] == "3-in-1 and settable", v
EOF
expect_fail "slice refuses a design with no printed part" 2 "no printed part" -- \
    slice designs/m12-setscrew.json -o "$tmp/none-printed"
finish
