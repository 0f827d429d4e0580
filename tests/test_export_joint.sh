#!/usr/bin/env bash
# tippe export --split --joint: both halves keep their flat cut face (each
# stands on z = 0), each gets a groove 2 mm deep in the inner half of the wall
# at the cut, and a separate ring fills both grooves with the clearance as
# play. Volumes read back with numpy-stl (tests/export_check.py) against the
# closed forms from the design file alone: the halves and the ring add up to
# the whole less the play. Usage: test_export_joint.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
"$py" -c "import stl" 2>/dev/null || skip "numpy-stl (Debian python3-stl) is not installed"
checker=tests/export_check.py

"$tippe" export designs/m12-setscrew.json -o "$tmp/whole" --format stl --json >"$tmp/whole.json" 2>/dev/null
"$tippe" export designs/m12-setscrew.json -o "$tmp/j" --format stl --split --joint --json >"$tmp/j.json" 2>"$tmp/j.err" ||
    bad "export --split --joint: $(cat "$tmp/j.err")"
for b in body-lower body-upper joint-ring; do
    "$py" "$checker" stl "$tmp/j/m12-setscrew-$b.stl" >"$tmp/$b.json" 2>/dev/null
done
"$py" "$checker" stl "$tmp/whole/m12-setscrew-body.stl" >"$tmp/body.json" 2>/dev/null
"$py" - "$tmp" designs/m12-setscrew.json <<'EOF' && ok || bad "joint: volumes or shapes differ from the closed forms"
import json, math, sys
t, design = sys.argv[1], json.load(open(sys.argv[2]))
v = {b: json.load(open(f"{t}/{b}.json")) for b in ["body-lower", "body-upper", "joint-ring", "body"]}
for b, s in v.items():
    assert s["open_edges"] == 0 and s["inconsistent_edges"] == 0 and s["degenerate_facets"] == 0, b
    assert b == "body" or abs(s["min"][2]) < 1e-9, (b, "stands on z = 0")
R, c, h = design["radius_mm"], 0.2, 2.0
ra = design["parts"][1]["radius_mm"] + c       # the hole as printed: the wall's inner edge
mid = (ra + R) / 2                             # the wall at the cut spans ra .. R
ring = math.pi * ((mid - c) ** 2 - ra ** 2) * (2 * h - c)
grooves = 2 * math.pi * (mid ** 2 - ra ** 2) * h
# the ring's mesh: inscribed polygons of >= 124 sides, low by < 0.1 %
assert abs(v["joint-ring"]["volume_mm3"] - ring) < 1e-3 * ring, (v["joint-ring"]["volume_mm3"], ring)
assert abs(v["joint-ring"]["max"][2] - (2 * h - c)) < 1e-5
assert abs(v["joint-ring"]["max"][0] - (mid - c)) < 1e-5
total = v["body-lower"]["volume_mm3"] + v["body-upper"]["volume_mm3"] + v["joint-ring"]["volume_mm3"]
want = v["body"]["volume_mm3"] - grooves + ring
print("halves + ring", total, "whole less the play", want)
# meshes of the same chord: their discretisations differ by < 0.1 % of the whole
assert abs(total - want) < 1e-3 * v["body"]["volume_mm3"]
EOF
expect_fail "--joint without --split" 2 "--joint needs --split" -- export designs/m12-setscrew.json -o "$tmp/x" --joint
# a wall too thin for a ring: a 1.5 mm shell gets a warning, no ring
json_edit designs/shell-rod-iron.json "$tmp/thin.json" 'd["parts"][0]["thickness_mm"] = 1.5; d["materials"] = "'"$(pwd)"'/designs/materials.json"'
"$tippe" export "$tmp/thin.json" -o "$tmp/thin" --format stl --split --joint >/dev/null 2>"$tmp/thin.err"
check "a 1.5 mm wall: warned, no joint ring written" \
    bash -c "grep -q 'no joint ring there' '$tmp/thin.err' && ! ls '$tmp/thin' | grep -q joint-ring"
finish
