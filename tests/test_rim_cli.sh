#!/usr/bin/env bash
# Issue 35 through the command: the M12's launches on its rims.
#  - every energy-cone verdict's end angle lies inside the cone it claims (a contact
#    regime lost across a long implicit step once ran the rest pole's rim at 165 deg
#    and "proved" no_tip there: seed 7's second launch under the patch law);
#  - check says where the top stood on its rim and how much spin the rim drained.
source "$(dirname "$0")/lib.sh"
setup "$@"

"$tippe" launch designs/m12-setscrew.json --z2 10 -n 2 --seed 7 --friction patch \
    --table laminate --no-radius-sensitivity --csv "$tmp/p.csv" >/dev/null 2>"$tmp/err" ||
    bad "launch failed: $(cat "$tmp/err")"
check "patch law on the rims: every energy-cone no_tip ends within 0.25 rad of upright" \
    python3 - "$tmp/p.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
assert len(rows) == 2
bad = [r for r in rows if r["decided_by"] == "energy_cone" and r["verdict"] == "no_tip"
       and float(r["theta_final_rad"]) >= 0.25]
assert not bad, bad
PY

"$tippe" check designs/m12-setscrew.json --z2 5 --t-end 60 >"$tmp/c.txt" 2>&1
check "check: the launch starts on the +z rim, modelled" \
    grep -q "^pole       the launch starts 3.9 deg from the +z pole.*(the contact follows the rim)" "$tmp/c.txt"
check "check: the time on the rim and its switches" grep -q "^rim        on a hole's rim for .* switches between rim and sphere" "$tmp/c.txt"
check "check: no INVALID contact on the default model" bash -c '! grep -q INVALID "$1"' _ "$tmp/c.txt"
"$tippe" check designs/m12-setscrew.json --z2 5 --t-end 60 --sphere-contact >"$tmp/s.txt" 2>&1
check "check --sphere-contact: the old model says INVALID" grep -q "INVALID" "$tmp/s.txt"
finish
