#!/usr/bin/env bash
# One launch under several friction laws side by side (issue 25.5): tippe check
# --friction viscous,patch runs tippe check's launch under each law and prints one
# table (law, verdict, how decided, over 90 deg, back below, end state, theta and energy lost
# at the end of the run), --json "laws" and --plot one figure of theta(t).
# Each law's row is what tippe check --friction LAW alone gives (the same launch
# and integration from the same command-line numbers: equal to 1e-12), its
# trajectory what check --friction LAW --csv writes (the CSV's 10 digits: 1e-9),
# and its energy lost is the dissipation D over E0, within the run's own energy
# balance error of E0 - E_end.
# Usage: test_check_laws.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/m12-setscrew.json
# on the whole sphere (--sphere-contact): the laws differ there as asserted below; the rim
# has its own tests (test_rim_cli.sh, test_physics_rim.c)
launch=(--z2 15 --spin 20rev/s --t-end 60 --sphere-contact)

"$tippe" check "$d" "${launch[@]}" --friction viscous,patch --json >"$tmp/laws.json" 2>"$tmp/err" ||
    bad "check --friction viscous,patch --json failed: $(cat "$tmp/err")"
for law in viscous patch; do
    "$tippe" check "$d" "${launch[@]}" --friction $law --json >"$tmp/$law.json" 2>/dev/null
    "$tippe" check "$d" "${launch[@]}" --friction $law --csv "$tmp/$law.csv" >/dev/null 2>&1
    check "$law: the row is tippe check --friction $law's verdict, decision and end state" \
        python3 - "$tmp/laws.json" "$tmp/$law.json" "$law" <<'PY'
import json, math, sys
o, c, law = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), sys.argv[3]
(r,) = [x for x in o["laws"] if x["friction"]["law"] == law]
assert r["friction"] == c["options"]["friction"], (r["friction"], c["options"]["friction"])
assert r["verdict"] == c["verdict"] and r["decided_by"] == c["decided_by"], (r["verdict"], c["verdict"])
for k in ("t_s", "theta_final_rad"):
    assert abs(r[k] - c[k]) <= 1e-12 * abs(c[k]) + 1e-300, (k, r[k], c[k])
assert o["initial"] == c["initial"], (o["initial"], c["initial"])
PY
    check "$law: the run is check --csv's trajectory (its end, 1e-9), energy lost = D / E0" \
        python3 - "$tmp/laws.json" "$tmp/$law.csv" "$law" <<'PY'
import csv, json, sys
o, law = json.load(open(sys.argv[1])), sys.argv[3]
(r,) = [x["run"] for x in o["laws"] if x["friction"]["law"] == law]
rows = list(csv.DictReader(open(sys.argv[2])))
last = rows[-1]
assert abs(float(last["t_s"]) - r["t_end_s"]) <= 1e-9 * r["t_end_s"], (last["t_s"], r["t_end_s"])
assert abs(float(last["theta_rad"]) - r["theta_end_rad"]) <= 1e-9 * max(r["theta_end_rad"], 1e-3)
assert abs(float(last["dissipated_J"]) - r["dissipated_J"]) <= 1e-9 * r["E0_J"]
assert abs(r["energy_lost"] - r["dissipated_J"] / r["E0_J"]) <= 1e-15
assert abs(r["E0_J"] - r["E_end_J"] - r["dissipated_J"]) <= (r["energy_rel_error"] + 1e-15) * r["E0_J"], r
assert r["samples"] == len(rows), (r["samples"], len(rows))
PY
done
check "the laws differ here: viscous flips to 180 deg, patch does not end inverted" \
    json_ok "$tmp/laws.json" "[x['verdict'] for x in o['laws']] == ['tip', 'hang'] and o['laws'][0]['run']['energy_lost'] < o['laws'][1]['run']['energy_lost']"

"$tippe" check "$d" "${launch[@]}" --friction viscous,patch --plot "$tmp/laws.png" >"$tmp/laws.txt" 2>"$tmp/err"
check "the text: one table with a row per law" \
    python3 - "$tmp/laws.txt" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
assert re.search(r"^law +verdict +decided +over 90 deg +back below +end state +at the end of the run: theta, energy lost$", t, re.M), t
assert re.search(r"^viscous +tip +trapped at .* s +[0-9.]+ s +- +180\.0 deg .*%", t, re.M), t
assert re.search(r"^patch +hang +observed at 60 s .*\(not proved\)", t, re.M), t
assert "centre at rest (U = V = 0), contact slip" in t
PY
check "--plot: one PNG, no PLplot warning" \
    bash -c '[ "$(head -c 8 "$1" | od -An -c | tr -d " ")" = "211PNG\r\n032\n" ] && ! grep -q WARNING "$2"' _ "$tmp/laws.png" "$tmp/err"

expect_fail "--csv with several laws" 2 "--csv writes one law's trajectory" -- \
    check "$d" --z2 15 --friction viscous,patch --csv "$tmp/x.csv"
expect_fail "a law twice" 2 "viscous twice" -- check "$d" --z2 15 --friction viscous,viscous
expect_fail "--mu-c with viscous alone" 2 "--mu-c is the Coulomb coefficient" -- \
    check "$d" --z2 15 --friction viscous --mu-c 0.3
expect_fail "launch takes one law" 2 "one law (tippe check compares several)" -- \
    launch "$d" --z2 15 --friction viscous,patch
finish
