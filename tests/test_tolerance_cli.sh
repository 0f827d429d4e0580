#!/usr/bin/env bash
# Tolerance bands as a user meets them: sweep prints and writes them, the JSON
# robust widths are width less both bands, compare shows robust widths, a bad
# tolerances block is refused naming the file and the entry, the banded plot is
# written. Usage: test_tolerance_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
m12=designs/m12-setscrew.json

out=$("$tippe" sweep "$m12")
check "sweep lists the tolerances it used" grep -q "independent, combined in quadrature" <<<"$out"
check "sweep gives a band per boundary" grep -q "band +/- mm" <<<"$out"
check "sweep gives robust widths" grep -q "robust (mm)" <<<"$out"

"$tippe" sweep "$m12" --json >"$tmp/m12.json"
check "sweep --json with bands: robust = width - both bands, never negative" \
    python3 - "$tmp/m12.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
assert o["bands"] and all(b["combined"] == "quadrature" for b in o["bands"])
assert {t["rule"] for t in o["tolerances"]} >= {"printed dimension", "filament density", "hardware mass"}
for b in o["bands"]:
    # quadrature <= linear sum, and both from the sensitivities
    s = {t["field"]: t["plus_minus"] for t in o["tolerances"]}
    terms = [abs(x["dz2_dfield"]) * s[x["field"]] for x in b["sensitivities"]]
    assert abs(sum(t * t for t in terms) ** 0.5 - b["band_mm"]) < 1e-12 * (1 + b["band_mm"])
    assert abs(sum(terms) - b["worst_mm"]) < 1e-12 * (1 + b["worst_mm"])
for z in o["zones"] + o["intervals"]:
    want = max(0.0, z["width_mm"] - z["band_from_mm"] - z["band_to_mm"])
    assert abs(z["robust_width_mm"] - want) < 1e-12, z
assert o["zones"][0]["band_from_mm"] == 0, "the sweep's start has no band"
PY

out=$("$tippe" compare "$m12" designs/shell-rod-nylon.json)
check "compare shows robust widths" bash -c 'grep -q "robust narrowest" <<<"$1" && grep -Eq "^\[1 \] .* [0-9]+\.[0-9]{3}$" <<<"$1" && grep -q "robust (mm)" <<<"$1"' _ "$out"
out=$("$tippe" compare "$m12" designs/shell-rod-nylon.json --wide)
check "compare --wide shows robust widths" grep -q "robust narrowest: .* mm" <<<"$out"
"$tippe" compare "$m12" --json >"$tmp/cmp.json"
check "compare --json has robust widths" python3 -c "
import json; o = json.load(open('$tmp/cmp.json'))
assert 'robust_zone_widths_mm' in o['designs'][0]"

# a printed body whose density is given inline is banded exactly as the same
# body of the named material (ABSplus, 1.08 g/cm^3): same tolerances but for
# the density's field name, same bands
"$tippe" sweep "$m12" --set 'parts.body.print={"infill": 0.4}' --json >"$tmp/named.json"
"$tippe" sweep "$m12" --set parts.body.density_g_cm3=1.08 --set 'parts.body.print={"infill": 0.4}' --json >"$tmp/inline.json"
check "a printed body with an inline density gets a printed body's tolerances and bands" \
    python3 - "$tmp/named.json" "$tmp/inline.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
rules = lambda o: sorted((t["field"].replace("materials.ABSplus", "parts.body"), t["plus_minus"], t["rule"]) for t in o["tolerances"])
assert rules(a) == rules(b), (rules(a), rules(b))
assert len(a["bands"]) == len(b["bands"]) >= 4, (len(a["bands"]), len(b["bands"]))
for x, y in zip(a["bands"], b["bands"]):
    # the same mass model (1e-12 relative in the moments): bands to 1e-9 mm
    assert abs(x["band_mm"] - y["band_mm"]) < 1e-9, (x["band_mm"], y["band_mm"])
PY

# a bad block: exit 2, file and entry named, nothing on stdout
json_edit "$m12" "$tmp/bad.json" 'd["tolerances"] = {"parts.bolt.height_mm": 0.1}; d["materials"] = "'"$(pwd)"'/designs/materials.json"'
expect_fail "unknown part in tolerances" 2 "$tmp/bad.json" 'tolerances["parts.bolt.height_mm"]' \
    "no part" -- sweep "$tmp/bad.json"
json_edit "$m12" "$tmp/bad2.json" 'd["tolerances"] = {"parts.screw.height_mm": "3 percent"}; d["materials"] = "'"$(pwd)"'/designs/materials.json"'
expect_fail "a percentage that is not one" 2 "$tmp/bad2.json" "not a percentage" -- sweep "$tmp/bad2.json"
expect_fail "--set tolerances with a bad field" 2 'tolerances["radius"]' -- \
    sweep "$m12" --set 'tolerances={"radius": 0.1}'

# the banded plot
"$tippe" sweep "$m12" --plot "$tmp/zones.png" >/dev/null
check "banded zone plot written" test -s "$tmp/zones.png"
# design-format.md's table of default tolerances names every rule sweep applies
# by default (a solid design, a printed one, a weighed one) and is one Markdown
# table (a blank line inside ends it: the rows after it were shown as text)
for set in "" "--set parts.body.print.measured_mass_g=25"; do
    "$tippe" sweep designs/m12-setscrew-printed.json $set --json >"$tmp/rules.json"
    check "design-format.md's default tolerances table has every rule sweep applies ($set)" \
        python3 - "$tmp/rules.json" "$tmp/m12.json" docs/design-format.md <<'PY'
import json, re, sys
rules = {t["rule"] for f in sys.argv[1:3] for t in json.load(open(f))["tolerances"]}
doc = open(sys.argv[3]).read()
start = doc.index("Defaults (a field the block leaves out):")
table = doc[start:].split("\n\n")[1]          # the first block after the line
rows = {m.group(1).strip() for m in re.finditer(r"^\| ([^|]+)\|", table, re.M)}
missing = rules - rows
assert not missing, ("not in the table", missing, rows)
assert "patch radius" in rows, rows             # the table's last row: one table
PY
done

# docs/printing.md's table of the print model's error term, three rows against
# the program as it is (tools/model_error_table.py makes the whole table: 42
# sheets); a merge that moves the bands left rows of it stale before (the
# blind-hole ball at 50 % read "3-in-1 on paper only" where build said not 3-in-1)
check "docs/printing.md's model_error table: three rows as tippe build gives them" \
    env TIPPE="$tippe" python3 tools/model_error_table.py --check \
    drilled-ball-blind-printed:50 m12-setscrew-printed:50 shell-rod-nylon-printed:15

finish
