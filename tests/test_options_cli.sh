#!/usr/bin/env bash
# The shared option parser (src/cli/options.c) as a user meets it in every verb:
# "--opt=value" and "--opt value" mean the same, numbers may carry a unit of
# their option's family, out-of-range numbers are refused with the allowed
# range, and --help shows units and defaults. Usage: test_options_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/m3-setscrew.json
m12=designs/m12-setscrew.json

# --opt=value and --opt value give the same report; 2cm is 20 mm.
"$tippe" eval "$d" --z2 20 --json >"$tmp/a.json" 2>&1
"$tippe" eval "$d" --z2=20 --json >"$tmp/b.json" 2>&1
"$tippe" eval --json "$d" --z2=2cm >"$tmp/c.json" 2>&1
check "--z2=20 and --z2 20 give the same JSON" cmp -s "$tmp/a.json" "$tmp/b.json"
# 2cm is converted to mm exactly (2 x 10): the same JSON to the last digit.
check "--z2 2cm is --z2 20" cmp -s "$tmp/a.json" "$tmp/c.json"

expect_fail "z2 out of range" 2 "--z2 '1e5'" "-1000 to 1000" "mm" -- eval "$d" --z2 1e5
expect_fail "z2 not a number" 2 "--z2 'abc'" -- eval "$d" --z2 abc
expect_fail "z2 unit of another family" 2 "--z2 '5rpm'" -- eval "$d" --z2 5rpm
expect_fail "z2 infinite" 2 "--z2 'inf'" -- eval "$d" --z2 inf
expect_fail "z2 NaN" 2 "--z2 'nan'" -- eval "$d" --z2 nan
# a mistyped unit is answered with the suffixes that would have worked
expect_fail "spin with a misspelt unit" 2 "--spin '20revs'" "or suffix rev/s, rpm" -- \
    simulate "$d" --z2 12 --spin 20revs
expect_fail "missing value" 2 "--z2 needs a value" -- eval "$d" --z2
# a bound as the help prints it (10 digits: 3.141592654 > pi) is the bound itself
sc=designs/scenarios/fig12-tip.json
check "--theta 3.141592654, the printed upper bound, is pi" \
    json_ok <("$tippe" simulate "$sc" --theta 3.141592654 --t-end 1 --json) \
    "o['initial']['theta_rad'] == 3.141592653589793"
check "--theta 180deg is pi" \
    json_ok <("$tippe" simulate "$sc" --theta 180deg --t-end 1 --json) \
    "o['initial']['theta_rad'] == 3.141592653589793"
expect_fail "beyond the printed bound" 2 "--theta '3.1416'" -- simulate "$sc" --theta 3.1416
expect_fail "required option" 2 "--z2 MM is required" -- eval "$d"
expect_fail "flag with a value" 2 "--json=1 takes no value" -- eval "$d" --z2 5 --json=1
expect_fail "unknown option" 2 "unknown option '--frobnicate'" -- eval "$d" --z2 5 --frobnicate
# Issue 19.10: an option is its whole name, never a prefix (getopt_long's default,
# which took --z for --z2 and --out for --output); the message names the option meant.
expect_fail "--js is not --json" 2 "unknown option '--js' (did you mean --json?)" -- \
    eval "$d" --z2 20 --js
expect_fail "--z=5 is not --z2" 2 "unknown option '--z' (did you mean --z2?)" -- eval "$d" --z=5
expect_fail "--z 5 is not --z2" 2 "unknown option '--z' (did you mean --z2?)" -- eval "$d" --z 5
expect_fail "--out is not --output" 2 "unknown option '--out' (did you mean --output?)" -- \
    optimise tests/data/optimise-small.json --out "$tmp/never.json"
check "--out: nothing written" test ! -e "$tmp/never.json"
expect_fail "--he is not --help" 2 "unknown option '--he'" -- eval "$d" --he
expect_fail "a prefix of several: all named" 2 "unknown option '--t' (did you mean one of" \
    "--tilt" "--t-end" -- launch "$m12" --z2 15 --t 5
expect_fail "--progres is not --progress" 2 "did you mean --progress?" -- \
    launch "$m12" --z2 15 -n 1 --progres
check "--z2=20 (whole name, joined value) still works" \
    json_ok <("$tippe" eval "$d" --z2=20 --json) "o['z2_mm'] == 20"
# a separate value that looks like an option is the value (here a bad --set)
expect_fail "--set --json: the value of --set" 2 "--set --json: expected FIELD=VALUE" -- \
    eval "$d" --z2 20 --set --json
expect_fail "two design files" 2 "at most 1 design file" -- eval "$d" "$d" --z2 5
expect_fail "no design file" 2 "no design file given" -- eval --z2 5

"$tippe" eval --help >"$tmp/help" 2>&1
check "eval --help exits 0" test $? -eq 0
check "eval --help shows the unit and range of --z2" grep -q "\[mm; required; -1000 .. 1000\]" "$tmp/help"
check "eval --help names the unit suffixes" grep -q "2.5cm" "$tmp/help"
"$tippe" eval -h >"$tmp/help2" 2>&1
check "-h is --help" cmp -s "$tmp/help" "$tmp/help2"

# --- one spin language: rad/s by default, rev/s and rpm by suffix ----------------
m12=designs/m12-setscrew.json
for spin in 125.66370614359172 20rev/s 1200rpm 125.66370614359172rad/s; do
    "$tippe" check "$m12" --z2 10 --spin "$spin" --accuracy fast --t-end 1 --json >"$tmp/s.json" 2>"$tmp/err"
    # 20 rev/s = 1200 rpm = 40 pi rad/s; the conversion costs at most a few ulps (1e-12 relative)
    check "check --spin $spin is 40 pi rad/s" json_ok "$tmp/s.json" \
        "abs(o['initial']['spin_rad_s'] - 40 * math.pi) < 1e-12 * 40 * math.pi"
done
"$tippe" launch "$m12" --z2 10 -n 1 --spin 10:20rev/s --accuracy fast --t-end 1 --json >"$tmp/l.json"
check "launch --spin 10:20rev/s: the unit on TO applies to FROM" json_ok "$tmp/l.json" \
    "all(abs(a - 2 * math.pi * b) < 1e-12 * a for a, b in zip(o['distribution']['spin_uniform_rad_s'], [10, 20]))"
check "launch --json: thresholds in rad/s" json_ok "$tmp/l.json" \
    "'n_minus_rad_s' in o['theory'] and not any(k.endswith('rev_s') for k in o['theory'])"

# --- defects 6 and 8: absurd numbers refused up front with the allowed range ------
expect_fail "map --spin 1e308" 2 "--spin '1e308:1e308:1'" "from 0 to 10000" -- \
    map "$m12" --z2 10:10:1 --spin 1e308:1e308:1
expect_fail "map grid beyond the memory bound" 2 "launches; at most 1e+07" -- \
    map "$m12" --z2 0:20:1000 --spin 1:40:1000 -n 100
expect_fail "simulate --sample-dt 1e-300" 2 "--sample-dt '1e-300'" "from 1e-09 to" -- \
    simulate designs/scenarios/fig12-tip.json --sample-dt 1e-300 --csv "$tmp/t.csv"
expect_fail "simulate samples beyond the bound" 2 "samples; at most 1e+06" -- \
    simulate designs/scenarios/fig12-tip.json --sample-dt 1e-6 --csv "$tmp/t.csv"
check "no CSV left by the refused runs" test ! -e "$tmp/t.csv"
expect_fail "simulate --theta-dot 1e160" 2 "--theta-dot '1e160'" "from -100000 to 100000" -- \
    simulate designs/scenarios/fig12-tip.json --theta-dot 1e160
expect_fail "simulate --set top.R=1e300" 2 "top.R" "outside the allowed 1e-06 .. 1000 m" -- \
    simulate designs/scenarios/fig12-tip.json --set top.R=1e300
expect_fail "sweep --from -1e308 --to 1e308" 2 "--from '-1e308'" "from -1000 to 1000" -- \
    sweep "$m12" --from -1e308 --to 1e308
"$tippe" sweep "$m12" --from -1000 --to 1000 >"$tmp/wide.txt" 2>&1
check "sweep over the widest allowed Z2 prints no NaN" bash -c '! grep -qi nan "$1"' _ "$tmp/wide.txt"

# --- --set is shown in every report it changes ---------------------------------
"$tippe" sweep "$m12" --set radius_mm=26 --json >"$tmp/sw.json"
check "sweep --json lists the --set changes" json_ok "$tmp/sw.json" "o['set'] == ['radius_mm=26']"
"$tippe" sweep "$m12" --json >"$tmp/sw0.json"
check "sweep --json without changes: an empty list" json_ok "$tmp/sw0.json" "o['set'] == []"
"$tippe" check "$m12" --z2 10 --set radius_mm=26 --accuracy fast --t-end 1 >"$tmp/ck.txt"
check "check text names the changes" grep -q "^changes    radius_mm=26" "$tmp/ck.txt"

# --- classify and simulate take a design ---------------------------------------
"$tippe" eval "$m12" --z2 12 --json >"$tmp/e.json"
"$tippe" classify "$m12" --z2 12 --json >"$tmp/c.json"
check "classify DESIGN --z2: the A/C and eps/R eval gives (same numbers, to the last digit)" \
    python3 -c "
import json,sys; e=json.load(open(sys.argv[1])); c=json.load(open(sys.argv[2]))
assert c['A_over_C'] == e['A_over_C'] and c['eps_over_R'] == e['eps_over_R']
assert c['subgroup'] == e['subgroup'] and c['n_minus_rad_s'] is not None" "$tmp/e.json" "$tmp/c.json"
expect_fail "classify: design and numbers" 2 "either the design or the numbers" -- \
    classify "$m12" --z2 12 --A-over-C 0.9
expect_fail "classify: design without --z2" 2 "--z2 MM is required with a design" -- classify "$m12"
# simulate DESIGN is tippe check's central hand launch: the same initial state (two
# code paths: tippe_scenario_for_design and tippe_launch_central) and the same verdict.
"$tippe" simulate "$m12" --z2 12 --spin 30rev/s --t-end 20 --accuracy fast --json >"$tmp/sim.json"
"$tippe" check "$m12" --z2 12 --spin 30rev/s --t-end 20 --accuracy fast --json >"$tmp/chk.json"
check "simulate DESIGN --z2 launches as tippe check does" python3 -c "
import json,sys; s=json.load(open(sys.argv[1])); c=json.load(open(sys.argv[2]))
for k in ('theta_rad', 'phi_dot_rad_s', 'spin_rad_s', 'U_m_s', 'V_m_s'):
    a, b = s['initial'][k], c['initial'][k]
    assert abs(a - b) <= 1e-12 * max(1, abs(b)), (k, a, b)   # same formulas, same doubles
assert s['verdict'] == c['verdict'], (s['verdict'], c['verdict'])" "$tmp/sim.json" "$tmp/chk.json"
expect_fail "simulate: design without --z2" 2 "--z2 MM is required with a design file" -- \
    simulate "$m12" --spin 20rev/s

# --- defect 6, issue 19.7: unit mistakes are named, with the unit they were probably in --
# The M12 design with every length in metres (each *_mm number x 1e-3): a radius of
# 0.025 "mm" was meant in metres. It is refused at the radius, before the travel or
# the parts that no longer fit are looked at (the travel message misled).
python3 - "$tmp/metres.json" "$(pwd)/designs/materials.json" <<'PY'
import json, sys
d = json.load(open("designs/m12-setscrew.json"))
def scale(o, key=""):
    if isinstance(o, dict):
        return {k: scale(v, k) for k, v in o.items()}
    if isinstance(o, list):
        return [scale(x, key) for x in o]
    return o * 1e-3 if key.endswith("_mm") and isinstance(o, (int, float)) else o
s = scale(d)
s["materials"] = sys.argv[2]
json.dump(s, open(sys.argv[1], "w"))
PY
expect_fail "a design in metres: refused at radius_mm, with the likely unit" 2 \
    "radius_mm: 0.025 mm is smaller than any tippe top" "did you mean metres? 0.025 m is 25 mm" -- \
    eval "$tmp/metres.json" --z2 0.005
expect_fail "radius_mm=0.025 alone: the unit, not the travel" 2 \
    "radius_mm: 0.025 mm is smaller than any tippe top" "did you mean metres? 0.025 m is 25 mm" -- \
    eval "$m12" --z2 1 --set radius_mm=0.025
"$tippe" eval "$m12" --z2 1 --set radius_mm=0.025 >/dev/null 2>"$tmp/err"
check "radius_mm=0.025: no word of the travel" sh -c "! grep -q travel '$tmp/err'"
expect_fail "radius_mm=25000: did you mean um" 2 \
    "radius_mm: 25000 mm is larger than any tippe top" "did you mean micrometres? 25000 um is 25 mm" -- \
    eval "$m12" --z2 1 --set radius_mm=25000
"$tippe" eval "$m12" --z2 1 --set parts.screw.radius_mm=0.0055 >/dev/null 2>"$tmp/err"
check "a screw radius of 0.0055 mm: warned, did you mean metres (5.5 mm)" \
    grep -q "warning: .*parts\[2\].radius_mm: 0.0055 mm (part 'screw').*did you mean metres? 0.0055 m is 5.5 mm" "$tmp/err"
# issue 25.5: a length above 0.01 mm but under 1 % of the radius, which in metres fits
# the ball (a 16 mm screw typed 0.016), and a travel typed in metres: warned with the hint;
# a 0.2 mm hole (200 mm would not fit) is not
"$tippe" eval "$m12" --z2 10 --set parts.screw.height_mm=0.016 >/dev/null 2>"$tmp/err"
check "a screw of 0.016 mm: warned, did you mean metres (16 mm)" \
    grep -q "warning: .*parts\[2\].height_mm: 0.016 mm (part 'screw') is under 1 % of the sphere's radius (25 mm.*did you mean metres? 0.016 m is 16 mm" "$tmp/err"
"$tippe" eval "$m12" --z2 0.01 --set 'travel_mm=[0,0.02]' >/dev/null 2>"$tmp/err"
check "a travel of 0 .. 0.02 mm: warned, did you mean metres (0 .. 20 mm)" \
    grep -q "warning: .*travel_mm: 0 .. 0.02 mm is under 1 % .*did you mean metres? 0 .. 0.02 m is 0 .. 20 mm" "$tmp/err"
"$tippe" eval designs/shell-rod-nylon.json --z2 1 --set parts.rod.radius_mm=0.2 --set parts.weight.inner_radius_mm=0.2 >/dev/null 2>"$tmp/err"
check "a 0.2 mm rod is no metres" sh -c "! grep -q metres '$tmp/err'"
# and a moving weight under 1 % of the top's mass (the M3 paper design's 0.167 g screw),
# with the centre of mass's shift over the travel
"$tippe" eval designs/m3-setscrew.json --z2 3 >/dev/null 2>"$tmp/err"
check "the M3's 0.167 g screw: a negligible moving weight" \
    grep -q "warning: .*the moving weight is 0.167 g, 0.24 % of the top's 70.47 g (under 1 %): over the whole travel it moves the centre of mass by 0.0554 mm" "$tmp/err"
"$tippe" eval "$m12" --z2 10 >/dev/null 2>"$tmp/err"
check "the M12's iron screw: no warning" test ! -s "$tmp/err"
expect_fail "a density of 7850 g/cm^3 is an error (kg/m^3? 7.85 g/cm^3)" 2 \
    "parts[2].density_g_cm3: 7850 g/cm^3 is denser than any solid (osmium" \
    "did you mean kg/m^3? 7850 kg/m^3 is 7.85 g/cm^3" -- \
    sweep "$m12" --set parts.screw.density_g_cm3=7850
expect_fail "22.7 g/cm^3, just above osmium, is an error" 2 "parts[2].density_g_cm3: 22.7 g/cm^3 is denser" -- \
    eval "$m12" --z2 1 --set parts.screw.density_g_cm3=22.7
"$tippe" eval "$m12" --z2 1 --set parts.screw.density_g_cm3=22.5 >/dev/null 2>&1
check "22.5 g/cm^3 (iridium, osmium) is accepted" test $? -eq 0
python3 -c '
import json, sys
t = json.load(open("designs/materials.json")); t["steel"]["density_g_cm3"] = 7850
json.dump(t, open(sys.argv[1], "w"))' "$tmp/materials-kg.json"
expect_fail "a table density in kg/m^3: names the table and the material" 2 \
    "materials-kg.json: steel.density_g_cm3: 7850 g/cm^3 is denser than any solid" -- \
    materials "$tmp/materials-kg.json"
for f in radius_mm parts.screw.radius_mm parts.screw.height_mm parts.screw.z_mm \
         parts.screw.density_g_cm3 parts.hole.radius_mm; do
    expect_fail "1e308 for $f names the field" 2 "(set by --set $f=1e308)" -- \
        eval "$m12" --z2 1 --set "$f=1e308"
done
"$tippe" sweep designs/shell-band.json >"$tmp/out" 2>"$tmp/err"
check "a shipped design: no warning" test ! -s "$tmp/err"

# slice's --help as the part as made has it: its 3MF prints the screw's hole at
# the tap drill whatever --clearance-mm says (test_slicer.sh slices it), and its
# per-object settings include the supports and the pinned ones, not the first
# layer (docs/printing.md); --help said "0 slices the mass model's part" alone
"$tippe" slice --help >"$tmp/slice-help.txt"
check "slice --help: the screw's hole printed at its tap drill whatever --clearance-mm says" \
    grep -q "the screw's hole is printed at its tap drill (or insert's pilot hole)" "$tmp/slice-help.txt"
check "slice --help: the 3MF's settings include the supports, not the first layer" \
    sh -c 'grep -q "supports and the settings the print model assumes" "$1" && grep -q "first layer.s height and width are its own" "$1"' _ "$tmp/slice-help.txt"

finish
