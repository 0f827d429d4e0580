#!/usr/bin/env bash
# tippe eval as a user drives it: every kind of bad design is refused with exit
# status 2 and a message that names the file and the JSON path; good designs
# give a table or JSON with the documented keys. Usage: test_eval_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
here=$(pwd)
cp "$here/designs/materials.json" "$tmp/"

# A small valid design to mutate: ABS shell, iron rod, iron bead.
write_base() {
    cat >"$1" <<'EOF'
{
  "name": "test top",
  "radius_mm": 25,
  "travel_mm": [0, 10],
  "parts": [
    {"name": "shell", "shape": "shell", "thickness_mm": 2.5, "material": "ABS"},
    {"name": "rod", "shape": "cylinder", "radius_mm": 3, "clip": "cavity", "material": "iron"},
    {"name": "weight", "shape": "tube", "inner_radius_mm": 3, "radius_mm": 10,
     "height_mm": 10, "material": "iron", "moving": true}
  ]
}
EOF
}
base=$tmp/base.json
write_base "$base"

# mutate NAME PYTHON: writes $tmp/NAME.json from the base design edited by a
# python snippet acting on the dict d.
mutate() { json_edit "$base" "$tmp/$1.json" "$2"; }

# --- good input -------------------------------------------------------------
if "$tippe" eval "$base" --z2 5 >"$tmp/out" 2>"$tmp/err" && grep -q "g mm^2" "$tmp/out" &&
    grep -q "A/C" "$tmp/out"; then ok; else bad "base design: $(cat "$tmp/err")"; fi

"$tippe" eval --help >"$tmp/out" 2>&1 && grep -q "usage: tippe eval" "$tmp/out" && ok ||
    bad "--help"

for f in designs/m12-setscrew.json designs/m3-setscrew.json designs/shell-rod-iron.json \
         designs/shell-rod-nylon.json designs/shell-band.json; do
    if "$tippe" eval "$f" --z2 5 --json >"$tmp/out.json" 2>"$tmp/err" &&
        python3 - "$tmp/out.json" <<'EOF'
import json, math, sys
o = json.load(open(sys.argv[1]))
need = ["mass_kg", "eps_m", "eps_over_R", "A_kg_m2", "C_kg_m2", "A_over_C", "z2_mm",
        "com_side", "design", "travel_mm", "physical_travel_mm", "parts"]
missing = [k for k in need if k not in o]
assert not missing, missing
# Consistency of the printed numbers (double printed to 15+ digits): 1e-12.
assert abs(o["A_over_C"] - o["A_kg_m2"] / o["C_kg_m2"]) < 1e-12 * o["A_over_C"]
assert abs(o["eps_over_R"] - o["eps_m"] / o["R_m"]) < 1e-12
assert o["z2_mm"] == 5 and o["com_side"] == 1
assert abs(sum(p["mass_kg"] for p in o["parts"]) - o["mass_kg"]) < 1e-12 * o["mass_kg"]
EOF
    then ok; else bad "$f --json: $(cat "$tmp/err")"; fi
done

# --- usage ------------------------------------------------------------------
expect_fail "no --z2" 2 "--z2" -- eval "$base"
expect_fail "bad --z2" 2 "--z2 'abc': expected a number of mm" -- eval "$base" --z2 abc
expect_fail "unknown option" 2 "unknown option '--frobnicate'" -- eval "$base" --z2 1 --frobnicate
expect_fail "no design" 2 "no design file" -- eval --z2 1
expect_fail "missing file" 2 "$tmp/nope.json" "cannot open" -- eval "$tmp/nope.json" --z2 1

# --- not JSON (with line and column) -------------------------------------------
printf '{\n  "name": "x",\n  "radius_mm": 25,,\n}\n' >"$tmp/notjson.json"
expect_fail "not JSON" 2 "$tmp/notjson.json:3:" "not valid JSON" -- eval "$tmp/notjson.json" --z2 1

# --- structure ----------------------------------------------------------------
mutate missing 'del d["radius_mm"]'
expect_fail "missing field" 2 "$tmp/missing.json" "radius_mm: missing" -- eval "$tmp/missing.json" --z2 1
mutate missing_part_field 'del d["parts"][2]["height_mm"]'
expect_fail "missing part field" 2 "parts[2].height_mm: missing" -- eval "$tmp/missing_part_field.json" --z2 1
mutate unknown 'd["parts"][1]["colour"] = "red"'
expect_fail "unknown field" 2 "$tmp/unknown.json" "parts[1].colour: unknown field" -- eval "$tmp/unknown.json" --z2 1
mutate unknown_top 'd["Radius_mm"] = 25'
expect_fail "unknown top field (case)" 2 "Radius_mm: unknown field" -- eval "$tmp/unknown_top.json" --z2 1
# A duplicate key cannot be written with json.dump: write it by hand.
sed 's/"thickness_mm": 2.5,/"thickness_mm": 2.5, "thickness_mm": 1,/' "$base" >"$tmp/dup.json"
expect_fail "duplicate key" 2 "$tmp/dup.json" "parts[0].thickness_mm: duplicate key" -- eval "$tmp/dup.json" --z2 1
mutate wrongtype 'd["radius_mm"] = "25"'
expect_fail "wrong type" 2 "radius_mm: must be a number, not a string" -- eval "$tmp/wrongtype.json" --z2 1
mutate wrongtype_bool 'd["parts"][2]["moving"] = 1'
expect_fail "wrong type (bool)" 2 "parts[2].moving: must be true or false" -- eval "$tmp/wrongtype_bool.json" --z2 1
mutate badshape 'd["parts"][1]["shape"] = "cone"'
expect_fail "unknown shape" 2 "parts[1].shape: unknown shape 'cone'" -- eval "$tmp/badshape.json" --z2 1
mutate dupname 'd["parts"][1]["name"] = "shell"'
expect_fail "duplicate part name" 2 "parts[1].name: 'shell' is already" -- eval "$tmp/dupname.json" --z2 1
# issue 28.8: an empty name is refused as an empty part name is
mutate noname 'd["name"] = ""'
expect_fail "empty design name" 2 "$tmp/noname.json: name: must not be empty" -- eval "$tmp/noname.json" --z2 1
mutate nopartname 'd["parts"][1]["name"] = ""'
expect_fail "empty part name" 2 "parts[1].name: must not be empty" -- eval "$tmp/nopartname.json" --z2 1

# --- values ---------------------------------------------------------------------
mutate negative 'd["parts"][2]["radius_mm"] = -10'
expect_fail "negative length" 2 "parts[2].radius_mm: must be positive" -- eval "$tmp/negative.json" --z2 1
mutate zero 'd["parts"][0]["thickness_mm"] = 0'
expect_fail "zero length" 2 "parts[0].thickness_mm: must be positive" -- eval "$tmp/zero.json" --z2 1
# issue 28.8: a subnormal length is bad input (exit 2, naming it), not a failed computation
mutate subnormal 'd["parts"][2]["height_mm"] = 1e-320'
expect_fail "subnormal part height" 2 "parts[2].height_mm:" "below 1e-09 mm" -- eval "$tmp/subnormal.json" --z2 1
mutate subnormal_r 'd["parts"][1]["radius_mm"] = 1e-320'
expect_fail "subnormal part radius" 2 "parts[1].radius_mm:" "below 1e-09 mm" -- eval "$tmp/subnormal_r.json" --z2 1
mutate zero_radius 'd["radius_mm"] = 0'
expect_fail "zero sphere radius" 2 "radius_mm: must be positive" -- eval "$tmp/zero_radius.json" --z2 1
mutate density 'd["parts"][1].pop("material"); d["parts"][1]["density_g_cm3"] = 0'
expect_fail "density not positive" 2 "parts[1].density_g_cm3: must be positive" -- eval "$tmp/density.json" --z2 1
mutate both 'd["parts"][1]["density_g_cm3"] = 7'
expect_fail "material and density" 2 "parts[1].density_g_cm3: give either" -- eval "$tmp/both.json" --z2 1
mutate material 'd["parts"][1]["material"] = "unobtainium"'
expect_fail "unknown material" 2 "parts[1].material: unknown material 'unobtainium'" -- eval "$tmp/material.json" --z2 1
python3 -c '
import json, sys
m = json.load(open(sys.argv[1])); m["iron"]["density_g_cm3"] = -7.87
json.dump(m, open(sys.argv[2], "w"))' "$tmp/materials.json" "$tmp/badmat.json"
mutate matfile 'd["materials"] = "badmat.json"'
expect_fail "bad materials table" 2 "$tmp/badmat.json" "iron.density_g_cm3: must be positive" -- eval "$tmp/matfile.json" --z2 1
mutate travel_order 'd["travel_mm"] = [10, 0]'
expect_fail "travel reversed" 2 "travel_mm: from (10 mm) must be less than" -- eval "$tmp/travel_order.json" --z2 1

# --- layout -----------------------------------------------------------------------
# a rod of the sphere's diameter: its rim (r = 3 mm, z = 25 mm) is outside the sphere
mutate protrude 'd["parts"][1].pop("clip"); d["parts"][1]["height_mm"] = 50'
expect_fail "part sticks out" 2 "parts[1]: part 'rod' sticks out of the sphere" -- eval "$tmp/protrude.json" --z2 1
# issue 19.6: a part longer than the ball is refused, even one that may protrude
mutate toolong 'd["parts"][1].pop("clip"); d["parts"][1]["height_mm"] = 60; d["parts"][1]["may_protrude"] = True'
expect_fail "part longer than the diameter" 2 "parts[1].height_mm: 60 mm is more than the sphere's diameter (50 mm)" -- eval "$tmp/toolong.json" --z2 1
mutate overlap 'd["parts"][2]["inner_radius_mm"] = 2'
expect_fail "parts overlap" 2 "part 'weight' overlaps part 'rod'" -- eval "$tmp/overlap.json" --z2 1
mutate overlap_fixed 'd["parts"].append({"name": "lump", "shape": "ball", "radius_mm": 4, "z_mm": -20, "material": "ABS"})'
expect_fail "fixed parts overlap" 2 "parts[3]: part 'lump' overlaps part 'shell'" -- eval "$tmp/overlap_fixed.json" --z2 1
mutate nomoving 'd["parts"][2]["moving"] = False'
expect_fail "no moving part" 2 "parts: no moving part" -- eval "$tmp/nomoving.json" --z2 1
mutate travel 'd["travel_mm"] = [0, 18]'
expect_fail "travel beyond physical" 2 "travel_mm: ends at 18 mm, beyond the physical travel" "touches part 'shell'" -- eval "$tmp/travel.json" --z2 1
# issue 25.5: a huge end puts the travel's middle where the weight cannot be; the message
# still gives the physical travel around the travel's start, as for a small overshoot
expect_fail "huge travel end, rod design" 2 "travel_mm: ends at 100 mm, beyond the physical travel -15.156 .. 15.156 mm" "touches part 'shell'" -- eval "$base" --z2 1 --set 'travel_mm=[0,100]'
expect_fail "huge travel end, screw design" 2 "travel_mm: ends at 100 mm, beyond the physical travel -23.455 .. 23.455 mm" "part 'screw' reaches the sphere's surface" -- eval designs/m3-setscrew.json --z2 1 --set 'travel_mm=[0,100]'
expect_fail "huge travel start, blind hole" 2 "travel_mm: starts at -100 mm, below the physical travel -7.500 .. 16.887 mm" -- eval designs/drilled-ball-blind.json --z2 1 --set 'travel_mm=[-100,10]'
expect_fail "a travel nowhere free names its middle" 2 "at Z2 = -150 mm (the middle of the travel) moving part 'screw' sticks out" -- eval designs/m3-setscrew.json --z2 1 --set 'travel_mm=[-200,-100]'
mutate void_out 'd["parts"][1]["radius_mm"] = 1; d["parts"].append({"name": "cut", "shape": "cylinder", "radius_mm": 2, "height_mm": 4, "void": True, "cut_from": "rod"})'
expect_fail "void outside its part" 2 "parts[3]: void 'cut' reaches outside" -- eval "$tmp/void_out.json" --z2 1
# Touching is fine: a setscrew in its drilled hole, a bead on its rod (the base).
expect_fail "Z2 outside the travel" 2 "$base" "travel_mm: Z2 = 12 mm is outside" -- eval "$base" --z2 12

# --- overrides --------------------------------------------------------------------
"$tippe" eval "$base" --z2 5 --json --set parts.rod.material=nylon >"$tmp/o.json" 2>"$tmp/err" &&
    grep -q '"nylon"' "$tmp/o.json" && ok || bad "--set parts.rod.material=nylon: $(cat "$tmp/err")"
expect_fail "override unknown part" 2 "--set parts.axle.material=nylon" "no part named 'axle'" -- eval "$base" --z2 1 --set parts.axle.material=nylon
expect_fail "override bad value" 2 "parts[2].height_mm: must be positive" "set by --set parts.weight.height_mm=0" -- eval "$base" --z2 1 --set parts.weight.height_mm=0
expect_fail "override unknown field" 2 "'radius' is not a design field" -- eval "$base" --z2 1 --set radius=30
expect_fail "override not JSON" 2 "'five' is not a JSON value" -- eval "$base" --z2 1 --set parts.weight.height_mm=five

# --- group and subgroup: eval's are those classify gives for eval's A/C, eps/R --
for z in 0 20; do
    "$tippe" eval designs/m3-setscrew.json --z2 $z --json >"$tmp/g.json" 2>"$tmp/g.err" # (the M3 warns of its light screw)
    k=$(python3 -c "import json; o=json.load(open('$tmp/g.json')); print(repr(o['A_over_C']), repr(o['eps_over_R']))")
    "$tippe" classify --A-over-C ${k% *} --eps-over-R ${k#* } --json >"$tmp/c.json" 2>&1
    check "eval --z2 $z: group and subgroup as classify's" python3 -c "
import json; e=json.load(open('$tmp/g.json')); c=json.load(open('$tmp/c.json'))
assert (e['group'], e['subgroup']) == (c['group'], c['subgroup']), (e['subgroup'], c['subgroup'])"
    "$tippe" eval designs/m3-setscrew.json --z2 $z >"$tmp/g.txt" 2>&1
    check "eval --z2 $z text names the subgroup" grep -q "subgroup $(python3 -c "import json; print(json.load(open('$tmp/c.json'))['subgroup'])")" "$tmp/g.txt"
done

# --- issue 19.6: a Z2 where the screw stands out of the sphere is marked -----------
# The M12 screw's rim (r = 5.5 mm, z = Z2 + 7.5 mm) leaves the R = 25 mm sphere at
# Z2 = sqrt(25^2 - 5.5^2) - 7.5 = 16.8875 mm; at Z2 = 18 it stands out by
# hypot(5.5, 25.5) - 25 = 1.0864 mm (the design samples the rim's radius: 1e-5 mm).
m12=designs/m12-setscrew.json
"$tippe" eval $m12 --z2 18 --json >"$tmp/p18.json" 2>/dev/null
check "eval --z2 18: model_valid false, the screw 1.0864 mm out near +z" python3 -c "
import json, math, sys
d = json.load(open(sys.argv[1])); p = d['protrusion']
assert d['model_valid'] is False and p['part'] == 'screw' and p['pole'] == '+z', d
assert abs(p['protrusion_mm'] - (math.hypot(5.5, 25.5) - 25)) < 1e-5, p
assert p['theta_range_rad'][0] < 1e-3, p   # theta = 0 (resting on the +z side) is on it
" "$tmp/p18.json"
"$tippe" eval $m12 --z2 18 >"$tmp/p18.txt" 2>&1
check "eval --z2 18 text: contact INVALID, naming the part" \
    grep -q "^contact  INVALID at Z2 = 18 mm: part 'screw' stands out of the sphere by 1.086 mm near the +z pole" "$tmp/p18.txt"
"$tippe" eval $m12 --z2 16.8 --json >"$tmp/p16.json" 2>/dev/null
check "eval --z2 16.8: the screw is inside, model_valid true" python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); assert d['model_valid'] is True and d['protrusion'] is None, d
" "$tmp/p16.json"
"$tippe" eval $m12 --z2 16.8 >"$tmp/p16.txt" 2>&1
check "eval --z2 16.8 text: no contact line" sh -c "! grep -q '^contact' '$tmp/p16.txt'"
quick=(--accuracy fast --t-end 5)
"$tippe" check $m12 --z2 18 "${quick[@]}" --json >"$tmp/c18.json" 2>/dev/null
check "check --z2 18: the verdict is marked model_valid false" python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); assert d['model_valid'] is False and d['protrusion']['part'] == 'screw', d
" "$tmp/c18.json"
"$tippe" check $m12 --z2 18 "${quick[@]}" >"$tmp/c18.txt" 2>&1
check "check --z2 18 text: contact INVALID after the verdict" \
    grep -q "^contact    INVALID at Z2 = 18 mm: .*so the verdict above is no prediction" "$tmp/c18.txt"
"$tippe" check $m12 --z2 12 "${quick[@]}" --json >"$tmp/c12.json" 2>/dev/null
check "check --z2 12: model_valid true" python3 -c "
import json, sys; assert json.load(open(sys.argv[1]))['model_valid'] is True" "$tmp/c12.json"
"$tippe" simulate $m12 --z2 19 "${quick[@]}" --json >"$tmp/s19.json" 2>/dev/null
check "simulate DESIGN --z2 19: model_valid false" python3 -c "
import json, sys; d = json.load(open(sys.argv[1])); assert d['model_valid'] is False, d" "$tmp/s19.json"
"$tippe" simulate $m12 --z2 19 "${quick[@]}" >"$tmp/s19.txt" 2>&1
check "simulate DESIGN --z2 19 text: contact INVALID" grep -q "^contact   INVALID at Z2 = 19 mm" "$tmp/s19.txt"
"$tippe" classify $m12 --z2 18 --json >"$tmp/k18.json" 2>/dev/null
check "classify DESIGN --z2 18: model_valid false" python3 -c "
import json, sys; d = json.load(open(sys.argv[1])); assert d['model_valid'] is False, d" "$tmp/k18.json"
"$tippe" launch $m12 --z2 19 -n 2 "${quick[@]}" --json >"$tmp/l19.json" 2>/dev/null
check "launch --z2 19: model_valid false" python3 -c "
import json, sys; d = json.load(open(sys.argv[1])); assert d['model_valid'] is False, d" "$tmp/l19.json"

finish
