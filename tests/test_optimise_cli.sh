#!/usr/bin/env bash
# tippe optimise as a user drives it: a small search (tests/data/optimise-small.json,
# ~150 candidates, well under a second), its best design re-measured by tippe sweep and
# launched by hand at the middle of each zone, determinism, and bad input.
# Usage: test_optimise_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
spec=tests/data/optimise-small.json

# --- a search, its outputs ----------------------------------------------------
"$tippe" optimise "$spec" -o "$tmp/best.json" --csv "$tmp/all.csv" --plot "$tmp/opt.png" \
    --json --threads 2 >"$tmp/res.json"
check "optimise exits 0" test $? -eq 0
check "optimise wrote BEST.json, the CSV and the plot" \
    test -s "$tmp/best.json" -a -s "$tmp/all.csv" -a -s "$tmp/opt.png"
check "the best design is 3-in-1 and feasible" json_ok "$tmp/res.json" \
    '[c for c in o["choices"] if c["best"]][0]["status"] == "ok" and [c for c in o["choices"] if c["best"]][0]["narrowest_zone_mm"] > 0'
# Every evaluation is a CSV row (header + evaluations).
rows=$(($(wc -l <"$tmp/all.csv") - 1))
check "the CSV has one row per evaluation ($rows)" json_ok "$tmp/res.json" "o['evaluations'] == $rows"

# --- BEST.json is a design every verb takes: sweep measures the same zones -------
"$tippe" sweep "$tmp/best.json" --json >"$tmp/sweep.json"
check "sweep accepts BEST.json" test $? -eq 0
# The optimiser re-measured its best with the same full sweep; both print zone ends
# found to 1e-7 mm, so widths that differ by more than 1e-6 mm are different zones.
check "sweep's zone widths agree with optimise's to 1e-6 mm" python3 - "$tmp/res.json" "$tmp/sweep.json" <<'EOF'
import json, sys
res = json.load(open(sys.argv[1])); sw = json.load(open(sys.argv[2]))
best = [c for c in res["choices"] if c["best"]][0]
for g in ("I", "II", "III"):
    a, b = best["zone_widths_mm"][g], sw["zone_widths_mm"][g]
    assert abs(a - b) <= 1e-6, (g, a, b)
assert abs(best["narrowest_zone_mm"] - sw["narrowest_zone_mm"]) <= 1e-6
assert sw["three_in_one"]
# The robust widths are sweep's bands on the same design: the same numbers.
assert abs(best["robust_narrowest_zone_mm"] - sw["robust_narrowest_zone_mm"]) <= 1e-6
assert best["robust_narrowest_zone_mm"] <= best["narrowest_zone_mm"]
# BEST.json's travel is its physical travel, rounded inward by 1e-9 mm.
assert all(abs(a - b) <= 2e-9 for a, b in zip(sw["physical_travel_mm"], sw["travel_mm"]))
EOF
# Independent geometry (tools/check_drilled_ball.py: its own mass integrals, closed-form
# travel, Theorem 5.1 by bisection). 1e-5 mm: tippe lets parts touch within 1e-6 mm, which
# moves the travel's end at the screw's corner by ~2e-6 mm; interior zone ends agree to 1e-9.
python3 tools/check_drilled_ball.py "$tmp/best.json" >"$tmp/indep.txt"
check "independent geometry gives the same zones to 1e-5 mm" python3 - "$tmp/indep.txt" "$tmp/sweep.json" <<'EOF'
import json, sys
line = [l for l in open(sys.argv[1]) if l.startswith("zones")][0].split()
indep = {"I": float(line[2]), "II": float(line[4]), "III": float(line[6])}
sw = json.load(open(sys.argv[2]))["zone_widths_mm"]
for g in indep:
    assert abs(indep[g] - sw[g]) <= 1e-5, (g, indep[g], sw[g])
EOF
check "BEST.json's notes say how it was found and the objective" \
    grep -q '"notes":.*Found by tippe optimise.*Narrowest zone' "$tmp/best.json"

# --- hand launches at the middle of each zone -----------------------------------
# Zone I straddles the balanced point, where the top has no preferred side and
# settles too slowly to be decided in a test; it is launched at the middle of its
# wider part on one side. 12 launches, default hand distribution, fast preset:
# the majority of the decided launches must be the zone's behaviour (I no_tip,
# II tip, III hang), with at least 3 decided.
python3 - "$tmp/sweep.json" >"$tmp/mids" <<'EOF'
import json, sys
sw = json.load(open(sys.argv[1]))
runs = {}
for z in sw["zones"]:
    if not z["reachable_mm"]:
        continue
    fam = z["group"] if z["group"] in ("I", "III") else "II"
    a, b = z["reachable_mm"]
    if fam == "I":  # each side of the balanced point on its own
        runs.setdefault("I", []).append((a, b))
    elif runs.get(fam) and abs(runs[fam][-1][1] - a) < 1e-9:
        runs[fam][-1] = (runs[fam][-1][0], b)
    else:
        runs.setdefault(fam, []).append((a, b))
want = {"I": "no_tip", "II": "tip", "III": "hang"}
for fam in ("I", "II", "III"):
    a, b = max(runs[fam], key=lambda r: r[1] - r[0])
    print(fam, 0.5 * (a + b), want[fam])
EOF
while read -r fam mid want; do
    # viscous friction: the zones are Theorem 5.1's, for a motion that dissipates until it
    # rests (eq 3.12); under Coulomb friction slow launches may stick and roll for ever
    "$tippe" launch "$tmp/best.json" --z2 "$mid" -n 12 --accuracy fast --json --threads 2 \
        --friction viscous >"$tmp/launch-$fam.json"
    check "launch at the middle of zone $fam (Z2 = $mid mm): majority $want" python3 - \
        "$tmp/launch-$fam.json" "$want" <<'EOF'
import json, sys
c = json.load(open(sys.argv[1]))["counts"]
decided = {k: v for k, v in c.items() if k != "undecided"}
assert sum(decided.values()) >= 3, c
top = max(decided, key=decided.get)
assert top == sys.argv[2] and decided[top] > sum(decided.values()) / 2, c
EOF
done <"$tmp/mids"

# --- same seed, same answer, at any number of threads ---------------------------
"$tippe" optimise "$spec" -o "$tmp/best1.json" --threads 1 >/dev/null
check "one thread and two give the same BEST.json" cmp -s "$tmp/best.json" "$tmp/best1.json"

# CRS2 draws random numbers: per choice, from NLopt's per-thread generator seeded by
# --seed and the choice, so three choices on one or two threads give the same file.
json_edit "$spec" "$tmp/crs.json" 'd["design"] = "'"$PWD"'/designs/drilled-ball-blind.json"; d["search"]["algorithm"] = "CRS2"; d["choose"]["parts.screw.material"] = ["brass", "iron", "steel"]; d["objective"] = "narrowest_zone"'
"$tippe" optimise "$tmp/crs.json" --seed 5 --threads 1 -o "$tmp/crs1.json" >/dev/null
"$tippe" optimise "$tmp/crs.json" --seed 5 --threads 2 -o "$tmp/crs2.json" >/dev/null
check "CRS2: same seed, same BEST.json on 1 and 2 threads" cmp -s "$tmp/crs1.json" "$tmp/crs2.json"

# Printable walls: with no min_wall_mm the wall is two line widths of the body as printed.
# A body printed with 3 mm lines needs 6 mm around the hole and under its floor; with the
# hole's centre below 8 mm its floor is under 7.4 mm, so some candidates are too thin.
json_edit designs/drilled-ball-blind.json "$tmp/wide-lines.json" 'd["materials"] = "'"$PWD"'/designs/materials.json"; d["parts"][0]["print"] = {"line_width_mm": 3, "infill": 1}'
json_edit "$spec" "$tmp/walls.json" 'd["design"] = "'"$tmp"'/wide-lines.json"; d["objective"] = "narrowest_zone"; d["vary"]["parts.hole.z_mm"] = [0, 8]'
"$tippe" optimise "$tmp/walls.json" --csv "$tmp/walls.csv" >/dev/null
check "two 3 mm perimeters: walls under 6 mm (and over the default 0.9 mm) are refused" \
    python3 - "$tmp/walls.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
thin = [r for r in rows if r["status"] == "thin wall"]
assert any(0.9 < float(r["wall_mm"]) < 6 for r in thin), "no candidate refused for a wall in 0.9 .. 6 mm"
assert all(float(r["wall_mm"]) >= 6 - 1e-9 for r in rows if r["status"] == "ok")
EOF

# --- bad input: a clear message naming the file and the field, exit 2, nothing written
json_edit "$spec" "$tmp/bad-key.json" 'd["design"] = "'"$PWD"'/designs/drilled-ball-blind.json"; d["vary"]["parts.screw.radius_mm"] = [6, 2]'
expect_fail "a reversed range" 2 "bad-key.json" "vary.parts.screw.radius_mm" "from < to" \
    -- optimise "$tmp/bad-key.json" -o "$tmp/never.json"
check "nothing written after bad input" test ! -e "$tmp/never.json"
json_edit "$spec" "$tmp/bad-obj.json" 'd["design"] = "'"$PWD"'/designs/drilled-ball-blind.json"; d["objective"] = "widest"'
expect_fail "an unknown objective" 2 "bad-obj.json" "objective" "narrowest_zone" \
    -- optimise "$tmp/bad-obj.json"
json_edit "$spec" "$tmp/bad-field.json" 'd["design"] = "'"$PWD"'/designs/drilled-ball-blind.json"; d["vary"]["parts.screw.colour_mm"] = [1, 2]'
expect_fail "a field the design does not have" 2 "colour_mm" -- optimise "$tmp/bad-field.json"
json_edit "$spec" "$tmp/bad-design.json" 'd["design"] = "no-such-design.json"'
expect_fail "a missing design" 2 "bad-design.json: design" "no-such-design.json" \
    -- optimise "$tmp/bad-design.json"
expect_fail "an output in a missing directory" 2 "-o" "$tmp/no/dir/best.json" \
    -- optimise "$spec" -o "$tmp/no/dir/best.json"
expect_fail "a plot with an unknown extension" 2 "--plot" -- optimise "$spec" --plot "$tmp/x.gif"
expect_fail "no spec" 2 "no spec" -- optimise
# --- issue 19.2: unknown options refused; no feasible design exits 1 writing nothing;
# tie chains resolved, cycles refused
base="$PWD/designs/drilled-ball-blind.json"
cat >"$tmp/brass.json" <<EOF
{"design": "$base", "vary": {"parts.hole.z_mm": [0, 25]},
 "choose": {"parts.screw.material": ["iron", "Brass"]}}
EOF
expect_fail "a material in the wrong case" 2 "brass.json" "choose.parts.screw.material[1]" \
    "unknown material 'Brass'" "did you mean 'brass'" -- optimise "$tmp/brass.json" -o "$tmp/never.json"
sed 's/"iron", "Brass"/"unobtainium"/' "$tmp/brass.json" >"$tmp/unob.json"
expect_fail "a material that is not in the table" 2 "unob.json" "unknown material 'unobtainium'" \
    -- optimise "$tmp/unob.json" -o "$tmp/never.json"
cat >"$tmp/heavy.json" <<EOF
{"design": "$base", "vary": {"parts.hole.z_mm": [0, 25]}, "constraints": {"max_weight_g": 0.001},
 "search": {"evaluations": 30, "polish_evaluations": 5}}
EOF
"$tippe" optimise "$tmp/heavy.json" -o "$tmp/never.json" --csv "$tmp/never.csv" \
    --plot "$tmp/never.png" >"$tmp/out" 2>"$tmp/err"
check "no feasible design: exit 1" test $? -eq 1
check "no feasible design: said, and the table shows why" \
    bash -c "grep -q 'no feasible design' '$tmp/err' && grep -q 'too heavy' '$tmp/out'"
check "no feasible design: no best claimed in the table, the closest marked" \
    bash -c "! grep -q -- '<- best' '$tmp/out' && grep -q 'closest (infeasible)' '$tmp/out' &&
             grep -q '^best     none' '$tmp/out' && ! grep -q 'narrowest zone [0-9]' '$tmp/out'"
check "no feasible design: nothing written" \
    bash -c "! ls '$tmp'/never.* 2>/dev/null | grep -q ."
# A chain: the screw's radius follows its height, the hole's radius the screw's
# (declared first, so the chain must be resolved, not read in file order).
cat >"$tmp/chain.json" <<EOF
{"design": "$base", "vary": {"parts.hole.z_mm": [0, 25], "parts.screw.height_mm": [8, 14]},
 "tie": {"parts.hole.radius_mm": {"follows": "parts.screw.radius_mm", "plus_mm": 0.2},
         "parts.screw.radius_mm": {"follows": "parts.screw.height_mm", "times": 0.35}},
 "search": {"evaluations": 40, "polish_evaluations": 10}}
EOF
"$tippe" optimise "$tmp/chain.json" -o "$tmp/chain-best.json" >/dev/null 2>"$tmp/err"
check "a tie chain optimises" test $? -eq 0
check "the written best keeps both ties (hole = screw + 0.2 = 0.35 height + 0.2, 1e-9 mm)" \
    python3 - "$tmp/chain-best.json" <<'EOF'
import json, sys
p = {x["name"]: x for x in json.load(open(sys.argv[1]))["parts"]}
h, s = p["hole"]["radius_mm"], p["screw"]
assert abs(s["radius_mm"] - 0.35 * s["height_mm"]) < 1e-9, (s,)
assert abs(h - (s["radius_mm"] + 0.2)) < 1e-9, (h, s)
EOF
cat >"$tmp/cycle.json" <<EOF
{"design": "$base", "vary": {"parts.hole.z_mm": [0, 25]},
 "tie": {"parts.hole.radius_mm": "parts.screw.radius_mm",
         "parts.screw.radius_mm": "parts.hole.radius_mm"}}
EOF
expect_fail "a cycle of ties" 2 "cycle.json" "cycle of ties" -- optimise "$tmp/cycle.json"
cat >"$tmp/tie-chosen.json" <<EOF
{"design": "$base", "vary": {"parts.hole.z_mm": [0, 25]},
 "choose": {"parts.hole.radius_mm": [5, 6]}, "tie": {"parts.hole.radius_mm": "parts.screw.radius_mm"}}
EOF
expect_fail "a tied field that is also chosen" 2 "tie.parts.hole.radius_mm" "also set by the choice" \
    -- optimise "$tmp/tie-chosen.json"
finish
