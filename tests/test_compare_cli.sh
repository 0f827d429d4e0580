#!/usr/bin/env bash
# tippe compare: fits 100 columns (or --wide side by side), writes CSV, JSON and
# a plot of the zone bars, and --set N: changes one design only.
# Usage: test_compare_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
a=designs/m12-setscrew.json
b=designs/m3-setscrew.json
c=designs/shell-rod-nylon.json

"$tippe" compare "$a" "$b" "$c" >"$tmp/t.txt"
check "compare exits 0" test $? -eq 0
check "compare's table fits 100 columns" bash -c '! awk "length > 100" "$1" | grep -q .' _ "$tmp/t.txt"
"$tippe" compare "$a" "$b" "$c" --wide >"$tmp/w.txt"
# Issue 19.11: the families a design has, one space between them, whichever are
# missing (shell-band has only group III: "no (III)", once printed "no ( III)").
"$tippe" compare "$a" designs/shell-band.json >"$tmp/f.txt"
check "compare: 'yes (I II III)' for M12, 'no (III)' for the band" python3 - "$tmp/f.txt" <<'PY'
import re, sys
rows = [l for l in open(sys.argv[1]) if re.match(r"\[\d", l)][-2:]
assert "yes (I II III)" in rows[0] and "no (III)" in rows[1], rows
PY
"$tippe" compare "$b" designs/shell-band.json --wide >"$tmp/fw.txt"
check "compare --wide: '3-in-1: no (I II)' and '3-in-1: no (III)'" \
    bash -c 'grep -q "3-in-1: no (I II) " "$1" && grep -q "3-in-1: no (III) *$" "$1"' _ "$tmp/fw.txt"
check "--wide puts the designs side by side (3 x 44 columns)" \
    bash -c 'awk "length > 100" "$1" | grep -q .' _ "$tmp/w.txt"

"$tippe" compare "$a" "$b" --json --set 2:radius_mm=26 >"$tmp/s.json"
"$tippe" compare "$a" "$b" --json >"$tmp/n.json"
check "--set 2: changes the second design only, and says so" python3 - "$tmp/s.json" "$tmp/n.json" <<'PY'
import json, sys
s, n = (json.load(open(f))["designs"] for f in sys.argv[1:])
assert s[0]["set"] == [] and s[1]["set"] == ["radius_mm=26"]
assert s[0]["zones"] == n[0]["zones"]            # design 1 untouched, to the last digit
assert s[1]["zones"] != n[1]["zones"]            # design 2 is the variant
PY
"$tippe" compare "$a" "$b" --set radius_mm=26 --json >"$tmp/all.json"
check "--set without N changes every design" json_ok "$tmp/all.json" \
    "all(d['set'] == ['radius_mm=26'] for d in o['designs'])"

"$tippe" compare "$a" "$b" "$c" --csv "$tmp/z.csv" --plot "$tmp/z.png" --json >"$tmp/z.json"
check "compare CSV has one row per zone of each design, as the JSON" python3 - "$tmp/z.csv" "$tmp/z.json" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
o = json.load(open(sys.argv[2]))
want = [(i + 1, len(d["intervals"])) for i, d in enumerate(o["designs"])]
got = [(i, sum(1 for r in rows if int(r["design_index"]) == i)) for i, _ in want]
assert [g for _, g in got] == [w for _, w in want], (got, want)
for r in rows:   # widths add up: to - from = width (printed to 10 digits)
    assert abs(float(r["z2_to_mm"]) - float(r["z2_from_mm"]) - float(r["width_mm"])) < 1e-8
    assert 0 <= float(r["robust_width_mm"]) <= float(r["width_mm"]) + 1e-9
PY
check "compare --plot is a PNG" python3 -c "
import sys; assert open(sys.argv[1], 'rb').read(8) == b'\x89PNG\r\n\x1a\n'" "$tmp/z.png"
expect_fail "--set to a design that is not there" 2 "--set '3:radius_mm=26'" "1 .. 2" -- \
    compare "$a" "$b" --set 3:radius_mm=26
expect_fail "compare plot format" 2 "--plot" -- compare "$a" --plot "$tmp/z.gif"
# issue 25.5: names alike in their first 40 characters are not cut alike: the summary
# widens its name column to the whole names (a name cut says so with "~"), and --wide
# names its columns whole above the table
one=(--set "1:name=M12 setscrew in a solid ABS ball, printed at 15 % infill, variant one")
two=(--set "2:name=M12 setscrew in a solid ABS ball, printed at 15 % infill, variant two")
"$tippe" compare "$a" "$a" "${one[@]}" "${two[@]}" >"$tmp/long.txt" 2>&1
check "compare: two long names alike at 40 characters stay whole in the summary" \
    bash -c 'grep -qE "^\[1 \] M12 setscrew .* variant one +yes" "$1" && grep -qE "^\[2 \] M12 setscrew .* variant two +yes" "$1"' _ "$tmp/long.txt"
"$tippe" compare "$a" "$a" "${one[@]}" "${two[@]}" --wide >"$tmp/longw.txt" 2>&1
check "compare --wide: the cut columns named whole" \
    bash -c 'grep -q "^column 1: .*variant one$" "$1" && grep -q "^column 2: .*variant two$" "$1"' _ "$tmp/longw.txt"
"$tippe" compare "$a" "$a" "${one[@]}" --set "2:name=B: M12 setscrew in a solid ABS ball, printed at 15 % infill" >"$tmp/longd.txt" 2>&1
check "compare: long names that differ early are cut with ~, summary rows within 100 columns" \
    bash -c 'grep -qE "^\[1 \] M12 setscrew in a solid ABS ball, print~ +yes" "$1" && ! grep -E "^\[[0-9] +\] " "$1" | awk "length > 100" | grep -q .' _ "$tmp/longd.txt"

finish
