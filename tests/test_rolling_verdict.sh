#!/usr/bin/env bash
# A top that sticks and rolls for ever at an intermediate angle has not flipped
# (issue 25.6): under Coulomb friction with sticking, `tip` only where the top
# is proved to stay in the inverted state (within 30 deg of pi); the M12 ball at
# Z2 = 15 mm launched at 30 rev/s rolls at about 138 deg for ever: bounded, by
# rolling, with its range, in check and simulate, and a run to 60 s stays there.
# Usage: test_rolling_verdict.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/m12-setscrew.json
launch=(--z2 15 --spin 30rev/s --friction coulomb)

"$tippe" check "$d" "${launch[@]}" --json >"$tmp/check.json" 2>"$tmp/err"
check "check: not tip but bounded, decided by rolling, with its range near 138 deg" \
    json_ok "$tmp/check.json" 'o["verdict"] == "bounded" and o["decided_by"] == "rolling" and 130 < math.degrees(o["theta_range_rad"][0]) <= math.degrees(o["theta_range_rad"][1]) < 145'
"$tippe" check "$d" "${launch[@]}" >"$tmp/check.txt" 2>&1
check "check's text: rolls for ever, over but not inverted" \
    grep -q "^verdict    bounded: sticks and rolls without slipping for ever.*not inverted (no flip)" "$tmp/check.txt"
"$tippe" simulate "$d" "${launch[@]}" --t-end 60 --json --csv "$tmp/run.csv" >"$tmp/sim.json" 2>"$tmp/err"
check "simulate: the same verdict" \
    json_ok "$tmp/sim.json" 'o["verdict"] == "bounded" and o["decided_by"] == "rolling"'
python3 - "$tmp/sim.json" "$tmp/run.csv" <<'EOF' && ok || bad "the run to 60 s leaves the range or reaches the inverted state"
import csv, json, math, sys
o = json.load(open(sys.argv[1]))
lo, hi = o["theta_range_rad"]
rows = [r for r in csv.DictReader(open(sys.argv[2])) if float(r["t_s"]) > o["decision_t_s"]]
assert float(rows[-1]["t_s"]) >= 60 - 1e-9, rows[-1]["t_s"]
th = [float(r["theta_rad"]) for r in rows]
assert lo - 1e-6 <= min(th) and max(th) <= hi + 1e-6, (min(th), max(th), lo, hi)
assert max(th) < math.pi - math.radians(30), max(th)
EOF
# the paper's viscous law: the same launch flips (tip, ends at pi)
"$tippe" check "$d" --z2 15 --spin 30rev/s --json >"$tmp/visc.json" 2>/dev/null
check "viscous: the same launch is a tip" json_ok "$tmp/visc.json" 'o["verdict"] == "tip"'
finish
