#!/usr/bin/env bash
# tippe export as a maker uses it, every file read back by an independent
# reader (tests/export_check.py: numpy-stl, zipfile + XML; admesh): closed,
# manifold, outward meshes whose volume is the body's exact volume, bounding
# boxes equal to the design's dimensions, a 3MF with the same bodies, drawing
# labels equal to the design's numbers and clear of each other (whole and
# --split), OpenSCAD rendering (when installed),
# and clear refusals. Usage: test_export_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
here=$(pwd)
# Debian's python3 has numpy-stl (python3-stl); a python3 earlier on PATH may not.
py=/usr/bin/python3
[ -x "$py" ] || py=python3
checker="$here/tests/export_check.py"
"$py" -c "import stl" 2>/dev/null || skip "numpy-stl (Debian python3-stl) is not installed"

# jq-free JSON probe: ok_py FILE EXPR (o is the JSON in FILE)
ok_py() { "$py" -c "import json,math,sys; o=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$1"; }

# --- every shipped design exports, every STL is a clean closed surface -------
for f in designs/*.json; do
    # design files only (not the materials table or the catalogue)
    "$py" -c 'import json,sys; sys.exit(0 if "parts" in json.load(open(sys.argv[1])) else 1)' "$f" || continue
    stem=$(basename "$f" .json)
    out=$tmp/$stem
    if ! "$tippe" export "$f" -o "$out" --json >"$tmp/$stem.json" 2>"$tmp/$stem.err"; then
        bad "$stem: export failed: $(cat "$tmp/$stem.err")"
        continue
    fi
    ok
    # every STL and the 3MF against the report (tests/export_check.py export)
    "$py" "$checker" export "$tmp/$stem.json" >"$tmp/$stem.check" 2>/dev/null
    check "$stem: STL and 3MF files read back clean, volumes and boxes agree: $(cat "$tmp/$stem.check")" \
        ok_py "$tmp/$stem.check" 'o["failures"] == [] and o["bodies"] >= 1'
    # every facet within --chord-mm of the true surface, and the true surface
    # within it of the mesh (tests/export_check.py chord: distances in the
    # (r, z) half-plane to the region the design file describes, overstated
    # by at most half the sampling step; 2e-6 mm for float32 coordinates)
    "$py" "$checker" chord "$tmp/$stem.json" >"$tmp/$stem.chord" 2>/dev/null
    check "$stem: the mesh keeps the chord tolerance: $(cat "$tmp/$stem.chord")" \
        ok_py "$tmp/$stem.chord" 'o["bodies"] and all(max(b["forward_max_mm"], b["reverse_max_mm"]) <= o["chord_mm"] + o["sample_step_mm"] / 2 + 2e-6 for b in o["bodies"])'
    # the section drawing's labels do not overlap one another (tests/svg_labels.py)
    check "$stem: section drawing labels clear of each other: $("$py" tests/svg_labels.py "$out/$stem-section.svg")" \
        "$py" tests/svg_labels.py "$out/$stem-section.svg"
    "$tippe" export "$f" -o "$out-split" --split --format svg >/dev/null 2>&1
    check "$stem --split: labels clear of each other and of the cut plane's: $("$py" tests/svg_labels.py "$out-split/$stem-section.svg")" \
        "$py" tests/svg_labels.py "$out-split/$stem-section.svg"
    # admesh, a second independent reader of each STL
    for stl in "$out"/*.stl; do
        command -v admesh >/dev/null || break
        admesh "$stl" >"$tmp/admesh.txt" 2>&1
        check "$stl: admesh: no open edge, degenerate facet, backwards edge or normal to fix" \
            bash -c "grep -qE '^Facets with 1 disconnected edge *: *0 ' '$tmp/admesh.txt' && grep -qE '^Degenerate facets *: *0\$' '$tmp/admesh.txt' && grep -qE '^Backwards edges *: *0\$' '$tmp/admesh.txt' && grep -qE '^Normals fixed *: *0\$' '$tmp/admesh.txt'"
    done
done

# --- a band fused to the shell leaves no crack (an earlier optimum's band met the
# cavity's chord so nearly at a vertex that the union kept both walls, 1e-6 mm
# apart, 0.52 mm deep into the body)
"$tippe" export tests/data/shell-band-crack.json -o "$tmp/crack" --format stl --json >"$tmp/crack.json" 2>/dev/null
"$py" "$checker" chord "$tmp/crack.json" >"$tmp/crack.chord" 2>/dev/null
check "a band fused to the shell: no crack, the chord tolerance kept: $(cat "$tmp/crack.chord")" \
    ok_py "$tmp/crack.chord" 'o["bodies"] and all(b["forward_max_mm"] <= o["chord_mm"] + o["sample_step_mm"] / 2 + 2e-6 for b in o["bodies"])'

# --- exact volumes and bounding boxes from the design file alone ---------------
m12=$tmp/m12-setscrew.json
"$py" "$checker" exact designs/m12-setscrew.json >"$tmp/m12-exact.json"
"$py" - "$m12" "$tmp/m12-exact.json" <<'EOF' && ok || bad "m12: tippe's exact volume or bounding box differs from the napkin-ring formula"
import json, math, sys
r = json.load(open(sys.argv[1])); e = json.load(open(sys.argv[2]))
R, a, c, chord = e["radius_mm"], e["hole_radius_mm"], r["clearance_mm"], r["chord_mm"]
assert r["holes_with_clearance"] == ["hole"] and c == 0.2 and not r["clearance_in_mass_model"]
b = r["bodies"][0]
# a ball less an axial through hole of radius a + c: 4/3 pi (R^2 - (a + c)^2)^(3/2)
ring = 4 / 3 * math.pi * (R * R - (a + c) ** 2) ** 1.5
assert abs(b["exact_volume_mm3"] - ring) < 1e-9 * ring, (b["exact_volume_mm3"], ring)
# bounding box: the ball's equator exactly (a vertex there), the hole's rim
# within the chord tolerance
for k in range(2):
    assert abs(b["bbox_max_mm"][k] - R) < 1e-6 and abs(b["bbox_min_mm"][k] + R) < 1e-6
zt = math.sqrt(R * R - (a + c) ** 2)
assert zt - chord <= b["bbox_max_mm"][2] <= zt + 1e-6 and abs(b["bbox_min_mm"][2] + b["bbox_max_mm"][2]) < 1e-9
EOF
"$py" "$checker" exact designs/shell-rod-iron.json >"$tmp/sr-exact.json"
"$py" - "$tmp/shell-rod-iron.json" "$tmp/sr-exact.json" <<'EOF' && ok || bad "shell-rod-iron: volume or bounding box"
import json, sys
r = json.load(open(sys.argv[1])); e = json.load(open(sys.argv[2]))
b = r["bodies"][0]; R = e["radius_mm"]
assert len(r["bodies"]) == 1 and b["name"] == "shell"   # the iron rod is hardware
assert abs(b["exact_volume_mm3"] - e["shell_mm3"]) < 1e-9 * e["shell_mm3"]
for k in range(3):
    assert abs(b["bbox_max_mm"][k] - R) < 1e-6 and abs(b["bbox_min_mm"][k] + R) < 1e-6
assert any("--split" in w and "'rod'" in w for w in r["warnings"])  # closed around the rod
EOF

# --- eval reports the printed volume export writes ----------------------------
"$tippe" eval designs/m12-setscrew.json --z2 5 --json >"$tmp/eval.json" 2>/dev/null
"$py" - "$tmp/eval.json" "$m12" <<'EOF' && ok || bad "eval's printed_bodies volume differs from export's"
import json, sys
e = json.load(open(sys.argv[1])); r = json.load(open(sys.argv[2]))
assert [b["name"] for b in e["printed_bodies"]] == [b["name"] for b in r["bodies"]]
for pb, b in zip(e["printed_bodies"], r["bodies"]):
    assert abs(pb["volume_mm3"] - b["exact_volume_mm3"]) < 1e-9 * b["exact_volume_mm3"]
EOF

# --- convergence: the volume error falls in proportion to --chord-mm ------------
# (chord sag ~ step^2 and the volume deficit ~ sag: order 1 in the chord, 2 in
# the facets' angle), for a solid ball and for the thin shell with its band,
# whose inner wall errs the other way; and within chord x area at every chord
for d in m12-setscrew shell-band-best; do
    for c in 0.04 0.02 0.01 0.005; do
        "$tippe" export designs/$d.json -o "$tmp/conv$d$c" --format stl --chord-mm $c --json >"$tmp/conv$d$c.json" 2>/dev/null
        "$py" "$checker" stl "$tmp/conv$d$c"/*.stl >"$tmp/conv$d$c.stl.json" 2>/dev/null
    done
    "$py" - "$tmp" "$d" <<'EOF' && ok || bad "$d: volume error does not converge at order 1 in --chord-mm"
import json, math, sys
t, d = sys.argv[1], sys.argv[2]; errs = []
for c in ["0.04", "0.02", "0.01", "0.005"]:
    r = json.load(open(f"{t}/conv{d}{c}.json")); s = json.load(open(f"{t}/conv{d}{c}.stl.json"))
    exact = r["bodies"][0]["exact_volume_mm3"]
    errs.append(abs(s["volume_mm3"] - exact))
    assert errs[-1] <= float(c) * s["area_mm2"], (c, errs[-1], s["area_mm2"])
orders = [math.log2(errs[i] / errs[i + 1]) for i in range(3)]
print(d, "errors (mm^3)", errs, "orders", orders)
# ceil() rounding of the step counts moves each ratio by a few %: 0.8 .. 1.2
assert all(0.8 < p < 1.2 for p in orders), orders
EOF
done

# --- split: two halves standing on their cut faces, volumes add up ------------
"$tippe" export designs/m12-setscrew.json -o "$tmp/split" --split --format stl,3mf --json >"$tmp/split.json" 2>/dev/null
for h in lower upper; do "$py" "$checker" stl "$tmp/split/m12-setscrew-body-$h.stl" >"$tmp/split-$h.json" 2>/dev/null; done
"$py" - "$tmp" <<'EOF' && ok || bad "split halves"
import json, sys
t = sys.argv[1]
r = json.load(open(f"{t}/split.json")); whole = json.load(open(f"{t}/m12-setscrew.json"))["bodies"][0]
lo = json.load(open(f"{t}/split-lower.json")); hi = json.load(open(f"{t}/split-upper.json"))
for s in (lo, hi):
    assert s["open_edges"] == 0 and s["inconsistent_edges"] == 0 and s["degenerate_facets"] == 0
    assert abs(s["min"][2]) < 1e-9          # flat cut face on the plate
# the halves of the ball, cut at its equator, make the whole ball ...
assert abs(lo["volume_mm3"] + hi["volume_mm3"] - whole["exact_volume_mm3"]) < 1e-3 * whole["exact_volume_mm3"]
# ... and are equal: the body is symmetric about its equator
assert abs(lo["volume_mm3"] - hi["volume_mm3"]) < 1e-6 * whole["exact_volume_mm3"]
EOF

# --- the drawing's labelled dimensions are the design's ---------------------
"$py" "$checker" svg "$tmp/shell-band/shell-band-section.svg" >"$tmp/svg.json"
"$py" - "$tmp/svg.json" designs/shell-band.json "$tmp/shell-band.json" <<'EOF' && ok || bad "drawing labels differ from the design"
import json, sys
s = json.load(open(sys.argv[1])); d = json.load(open(sys.argv[2])); r = json.load(open(sys.argv[3]))
parts = {p["name"]: p for p in d["parts"]}
want = {"sphere.radius_mm": d["radius_mm"], "z2_mm": r["z2_mm"],
        "travel_mm[0]": d["travel_mm"][0], "travel_mm[1]": d["travel_mm"][1],
        "shell.thickness_mm": parts["shell"]["thickness_mm"],
        "band.radial_semi_mm": parts["band"]["radial_semi_mm"],
        "band.axial_semi_mm": parts["band"]["axial_semi_mm"],
        "rod.diameter_mm": 2 * parts["rod"]["radius_mm"],
        "weight.diameter_mm": 2 * parts["weight"]["radius_mm"],
        "weight.height_mm": parts["weight"]["height_mm"]}
got = {x["name"]: x for x in s["dims"]}
for k, v in want.items():
    assert k in got, k
    assert abs(got[k]["mm"] - v) < 1e-9, (k, got[k], v)
    # and the text a person reads states that value
    assert any(abs(n - v) < 1e-9 for n in got[k]["numbers"]), (k, got[k])
EOF
check "PNG drawing is a PNG" bash -c "head -c 8 '$tmp/m12-setscrew/m12-setscrew-section.png' | od -c | grep -q 'P   N   G'"

# --- OpenSCAD (optional: installed in CI by tools/deps.sh) ---------------------
if command -v openscad >/dev/null; then
    scad=$tmp/m12-setscrew/m12-setscrew.scad
    for fn in 32 64; do
        openscad -q -D 'show="printed"' -D fn=$fn -o "$tmp/scad$fn.stl" "$scad" 2>"$tmp/scad.err" ||
            bad "openscad fn=$fn: $(cat "$tmp/scad.err")"
        "$py" "$checker" stl "$tmp/scad$fn.stl" >"$tmp/scad$fn.json" 2>/dev/null
    done
    "$py" - "$tmp" <<'EOF' && ok || bad "the OpenSCAD source renders a different volume"
import json, sys
t = sys.argv[1]
exact = json.load(open(f"{t}/m12-setscrew.json"))["bodies"][0]["exact_volume_mm3"]
v32 = json.load(open(f"{t}/scad32.json"))["volume_mm3"]; v64 = json.load(open(f"{t}/scad64.json"))["volume_mm3"]
# OpenSCAD's polygons are inscribed: error ~ fn^-2; Richardson removes that
# term, what is left is O(fn^-4) ~ (1.6e-2)^2 at fn = 32: 0.1 % is ample.
assert v32 < v64 < exact
extrapolated = v64 + (v64 - v32) / 3
print("openscad fn=32", v32, "fn=64", v64, "extrapolated", extrapolated, "exact", exact)
assert abs(extrapolated - exact) < 1e-3 * exact
EOF
else
    echo "$test_name: openscad not on PATH: the OpenSCAD render check is skipped"
fi

# --- warnings and refusals ----------------------------------------------------
cp designs/materials.json "$tmp/"
json_edit designs/shell-rod-iron.json "$tmp/thin.json" 'd["parts"][0]["thickness_mm"] = 0.5'
"$tippe" export "$tmp/thin.json" -o "$tmp/thin" --format stl >/dev/null 2>"$tmp/thin.err"
check "a 0.5 mm shell is exported with a thin-wall warning" grep -q "thinner than 0.90 mm" "$tmp/thin.err"
json_edit designs/m12-setscrew.json "$tmp/allgone.json" 'd["parts"][1] = {"name": "hole", "shape": "ball", "void": True, "cut_from": "body"}'
expect_fail "a void that removes the whole body" 2 "nothing of the printed parts" -- export "$tmp/allgone.json" -o "$tmp/allgone"
check "nothing written for it" test ! -e "$tmp/allgone"
json_edit designs/m12-setscrew.json "$tmp/metal.json" 'd["parts"][0]["material"] = "steel"'
expect_fail "a design with nothing printable" 2 "nothing to print" -- export "$tmp/metal.json" -o "$tmp/metal"
expect_fail "chord out of range" 2 "from 0.001 to 1" -- export designs/m12-setscrew.json -o "$tmp/bad" --chord-mm 0
check "bad usage leaves nothing" test ! -e "$tmp/bad"
expect_fail "unknown format" 2 "unknown format 'obj'" -- export designs/m12-setscrew.json -o "$tmp/bad" --format stl,obj
expect_fail "no output directory" 2 "--output DIR is required" -- export designs/m12-setscrew.json
touch "$tmp/afile"
expect_fail "output is a file" 2 "not a directory" -- export designs/m12-setscrew.json -o "$tmp/afile"
expect_fail "z2 outside the travel" 2 "outside the design's travel" -- export designs/m12-setscrew.json -o "$tmp/bad" --z2 40
"$tippe" export --help >"$tmp/help" && grep -q "clearance-mm MM" "$tmp/help" && ok || bad "--help"
finish
