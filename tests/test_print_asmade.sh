#!/usr/bin/env bash
# The part as made (issue 40, docs/printing.md "The part as made"): a hole printed at its tap
# drill (printed_radius_mm, or derived from the fit when the file gives none) and tapped after.
# The print model lays the body with the hole at the printed radius and cuts what lies inside the
# design's radius; every command (eval, sweep, build) models that one part.
# No slicer needed (test_slicer.sh holds it against PrusaSlicer's G-code).
# Usage: test_print_asmade.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
d=designs/m12-setscrew-printed.json

for f in 0.15 0.5; do
    # the hole as written: printed at its own radius (printed_radius_mm = radius_mm), no cut
    "$tippe" eval $d --z2 5 --json --set parts.body.print.infill=$f \
        --set parts.hole.printed_radius_mm=5.5 >"$tmp/plain-$f.json" &&
    "$tippe" eval $d --z2 5 --json --set parts.body.print.infill=$f \
        --set parts.hole.printed_radius_mm=5.125 >"$tmp/made-$f.json" &&
    "$tippe" eval $d --z2 5 --json --set parts.body.print.infill=$f >"$tmp/fit-$f.json" ||
        { bad "eval with printed_radius_mm at infill $f"; continue; }
    # without printed_radius_mm the file's hole (no fit: tapped, as tippe build prints it) is
    # printed at the M12's tap drill, 12 - 1.75 = 10.25 mm: the same part, the same numbers
    "$py" - "$tmp/made-$f.json" "$tmp/fit-$f.json" <<'EOF' && ok || bad "the tap drill derived from the fit at infill $f"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for k in ("mass_kg", "A_kg_m2", "C_kg_m2"):
    assert a[k] == b[k], (k, a[k], b[k])  # the same design computed twice: bit for bit
assert a["printed_parts"][0]["cut_mass_kg"] == b["printed_parts"][0]["cut_mass_kg"] > 0
EOF
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
# robust ranges are the as-made design's (the same design given printed_radius_mm), and tippe
# sweep and eval of the file as it is model that same part (one part, one truth): the same
# robust widths and zone ends as build's sheet, the same printed mass
for v in build made; do
    set=()
    [ $v = made ] && set=(--set parts.hole.printed_radius_mm=5.125)
    "$tippe" build $d -o "$tmp/b-$v" --no-export --json --set parts.body.print.infill=0.5 \
        "${set[@]}" >"$tmp/b-$v.json" 2>"$tmp/b-$v.err" || bad "build ($v): $(tail -2 "$tmp/b-$v.err")"
done
"$tippe" sweep $d --json --set parts.body.print.infill=0.5 >"$tmp/s.json" || bad "sweep"
"$tippe" build $d -o "$tmp/b-slide" --no-export --json --set parts.body.print.infill=0.5 \
    --hole slide >"$tmp/b-slide.json" 2>/dev/null || bad "build --hole slide"
"$tippe" sweep $d --json --set parts.body.print.infill=0.5 \
    --set parts.hole.printed_radius_mm=5.5 >"$tmp/s-plain.json" || bad "sweep, the hole as written"
"$py" - "$tmp/b-build.json" "$tmp/b-made.json" "$tmp/s.json" "$tmp/fit-0.5.json" \
    "$tmp/b-slide.json" "$tmp/s-plain.json" <<'EOF' && ok || bad "tippe build, sweep and eval model the part as made"
import json, sys
a, b, s, e, bs, sp = (json.load(open(f)) for f in sys.argv[1:7])
assert a["verdict"] == b["verdict"], (a["verdict"], b["verdict"])
# the same design computed twice: the same numbers (1e-9 mm: the sweep's own root tolerance)
def same_sheet(a, b):
    for x, y in zip(a["settings"], b["settings"]):
        assert (x["robust_width_mm"] is None) == (y["robust_width_mm"] is None), (x, y)
        if x["robust_width_mm"] is not None:
            assert abs(x["robust_width_mm"] - y["robust_width_mm"]) < 1e-9, (x, y)
same_sheet(a, b)
# the sheet against the sweep of the file as it is: each behaviour's robust width is the
# sweep's for its group, and its run's ends are zone ends of the sweep
def against_sweep(a, s):
    ends = [z["z2_from_mm"] for z in s["zones"]] + [z["z2_to_mm"] for z in s["zones"]]
    ends += s["physical_travel_mm"] + s["travel_mm"]
    for x in a["settings"]:
        if x["robust_width_mm"] is None:
            continue
        want = s["robust_zone_widths_mm"][x["group"]]
        assert abs(x["robust_width_mm"] - want) < 1e-9, (x["group"], x["robust_width_mm"], want)
        z = x["z2_from_mm"]
        assert min(abs(z - w) for w in ends) < 1e-9, (x["group"], z, ends)
against_sweep(a, s)
# and eval's printed part is build's: the same mass and cut (bit for bit: one model)
pa, pe = a["print"][0], e["printed_parts"][0]
assert pa["printed_mass_kg"] == pe["printed_mass_kg"], (pa["printed_mass_kg"], pe["printed_mass_kg"])
assert pa["cut_mass_kg"] == pe["cut_mass_kg"] > 0, (pa["cut_mass_kg"], pe["cut_mass_kg"])
# --hole slide prints the hole at its radius plus the clearance, not tapped: its sheet models
# the hole as written (printed_radius_mm = radius_mm), as the sweep given that does
against_sweep(bs, sp)
assert bs["print"][0]["cut_mass_kg"] == 0, bs["print"][0]
assert "printed_radius_mm=5.5" in bs["measure"].get("as_made_set", ""), bs["measure"]
assert any("the hole not tapped" in n for n in bs["notes"]), bs["notes"]
assert any("tapped after" in n and "(tippe sweep gives the same)" in n for n in a["notes"]), a["notes"]
EOF
finish
