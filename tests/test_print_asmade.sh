#!/usr/bin/env bash
# The part as made (issue 40, docs/printing.md "The part as made"): a hole printed at its tap
# drill (printed_radius_mm) and tapped after. The print model lays the body with the hole at the
# printed radius and cuts what lies inside the design's radius; tippe build models that part.
# No slicer needed (test_slicer.sh holds it against PrusaSlicer's G-code).
# Usage: test_print_asmade.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
d=designs/m12-setscrew-printed.json

for f in 0.15 0.5; do
    "$tippe" eval $d --z2 5 --json --set parts.body.print.infill=$f >"$tmp/plain-$f.json" &&
    "$tippe" eval $d --z2 5 --json --set parts.body.print.infill=$f \
        --set parts.hole.printed_radius_mm=5.125 >"$tmp/made-$f.json" ||
        { bad "eval with printed_radius_mm at infill $f"; continue; }
    "$py" - "$tmp/plain-$f.json" "$tmp/made-$f.json" <<'EOF' && ok || bad "the cut of the tapped M12 hole at infill $f"
import json, math, sys
p = json.load(open(sys.argv[1]))["printed_parts"][0]
m = json.load(open(sys.argv[2]))["printed_parts"][0]
# the cut: the solid ring between the printed hole's wall edge and the design's hole, over the
# hole's length in the ball. The wall's edge lies (w - s)/2 inside the printed outline
# (w 0.45 mm, s = w - 0.2 (1 - pi/4)), the walls (0.81 mm) are wider than the tap's 0.375 mm,
# so the ring is solid: pi (5.5^2 - r_in^2) 2 sqrt(25^2 - 5.5^2) mm^3 at 1.08 g/cm^3. The model
# slices in whole 0.2 mm layers where the ring is continuous: 1 % (its ends, ~0.5 mm of 48.8)
s = 0.45 - 0.2 * (1 - math.pi / 4)
r_in = 5.125 + (0.45 - s) / 2
want = math.pi * (5.5 ** 2 - r_in ** 2) * 2 * math.sqrt(25 ** 2 - 5.5 ** 2) * 1.08e-6
assert abs(m["cut_mass_kg"] - want) < 0.01 * want, (m["cut_mass_kg"], want)
assert p["cut_mass_kg"] == 0, p["cut_mass_kg"]
# printed at the tap drill, the part has its walls 0.375 mm further in and the infill beyond
# them, so it is lighter than printed at 11 mm by the cut less what the wider infill region
# holds: between the cut alone (solid walls 0.375 mm further out at 100 %) and a third of it
d = p["printed_mass_kg"] - m["printed_mass_kg"]
assert want / 3 < d < want, (d, want)
# plastic near the axis taken away: the body's A/C falls (A loses z^2 along the whole axis)
assert m["body_A_over_C"] < p["body_A_over_C"], (m["body_A_over_C"], p["body_A_over_C"])
EOF
done

# only a hole (a void cylinder) takes printed_radius_mm; the message names the field
expect_fail "printed_radius_mm on the screw" 2 "parts[2].printed_radius_mm: only a hole" -- \
    eval $d --z2 5 --set parts.screw.printed_radius_mm=5.125

# tippe build prints the hole at the tap drill and its sheet is the part as made: its verdict's
# robust ranges are the as-made design's (the same design given printed_radius_mm)
for v in build made; do
    set=()
    [ $v = made ] && set=(--set parts.hole.printed_radius_mm=5.125)
    "$tippe" build $d -o "$tmp/b-$v" --no-export --json --set parts.body.print.infill=0.5 \
        "${set[@]}" >"$tmp/b-$v.json" 2>"$tmp/b-$v.err" || bad "build ($v): $(tail -2 "$tmp/b-$v.err")"
done
"$py" - "$tmp/b-build.json" "$tmp/b-made.json" <<'EOF' && ok || bad "tippe build models the part as made"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert a["verdict"] == b["verdict"], (a["verdict"], b["verdict"])
for x, y in zip(a["settings"], b["settings"]):
    # the same design computed twice: the same numbers (1e-9 mm: the sweep's own root tolerance)
    assert (x["robust_width_mm"] is None) == (y["robust_width_mm"] is None), (x, y)
    if x["robust_width_mm"] is not None:
        assert abs(x["robust_width_mm"] - y["robust_width_mm"]) < 1e-9, (x, y)
EOF
finish
