#!/usr/bin/env bash
# tippe materials: lists the materials table a user's designs read (name,
# density, printable, source) and says which file that is; a missing or bad
# table is refused with a message that says how to fix it.
# Usage: test_materials_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

"$tippe" materials --json >"$tmp/m.json" 2>"$tmp/err"
check "materials --json exits 0" test $? -eq 0
# The listing is the file's content: every entry, in order, with its density and
# source as written (read independently here with Python's json).
check "materials --json lists designs/materials.json entry for entry" python3 - "$tmp/m.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
table = json.load(open("designs/materials.json"))
assert o["file"] == "designs/materials.json", o["file"]
assert [m["name"] for m in o["materials"]] == list(table)
for m in o["materials"]:
    t = table[m["name"]]
    assert m["density_g_cm3"] == t["density_g_cm3"] and m["source"] == t["source"]
    assert m["printable"] == t["printable"]
PY
"$tippe" materials >"$tmp/m.txt"
check "materials text names the file it read" grep -q "^materials table designs/materials.json" "$tmp/m.txt"
check "materials text has ABSplus at 1.080 g/cm^3" grep -Eq "^ABSplus +1\.080 +yes" "$tmp/m.txt"
check "materials text fits 100 columns" bash -c '! awk "length > 100" "$1" | grep -q .' _ "$tmp/m.txt"
"$tippe" materials designs/m12-setscrew.json >"$tmp/d.txt"
check "a design's table is the one it reads" grep -q "the table this design reads" "$tmp/d.txt"

mkdir -p "$tmp/lonely"
cp designs/m12-setscrew.json "$tmp/lonely/"
expect_fail "a design whose table is missing" 2 "$tmp/lonely/materials.json" "does not exist" \
    "copy designs/materials.json there" -- materials "$tmp/lonely/m12-setscrew.json"
expect_fail "a table that does not exist" 2 "cannot open" -- materials "$tmp/none.json"
printf '{"goo": {"density_g_cm3": -1, "source": "x", "printable": false}}\n' >"$tmp/bad.json"
expect_fail "a bad density" 2 "goo.density_g_cm3" "must be positive" -- materials "$tmp/bad.json"
check "materials --help exits 0" exits 0 materials --help
finish
