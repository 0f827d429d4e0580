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

# A design without a "materials" field and without materials.json beside it reads
# the shipped table (here the checkout's designs/), and says so; one that names a
# table that is missing is refused.
mkdir -p "$tmp/lonely"
cp designs/m12-setscrew.json "$tmp/lonely/"
"$tippe" materials "$tmp/lonely/m12-setscrew.json" >"$tmp/l.txt" 2>&1
check "a lonely design's table is the shipped one" grep -q "^materials table $PWD/designs/materials.json" "$tmp/l.txt"
check "... and the listing says why" grep -q "no materials.json beside it" "$tmp/l.txt"
"$tippe" eval "$tmp/lonely/m12-setscrew.json" --z2 5 --json >"$tmp/l.json" 2>"$tmp/l.err"
check "eval of a lonely design exits 0" test $? -eq 0
check "... with a note naming the shipped table" grep -q "note: $tmp/lonely/m12-setscrew.json: materials: no materials.json beside the design: its materials are those of the shipped table $PWD/designs/materials.json" "$tmp/l.err"
"$tippe" eval designs/m12-setscrew.json --z2 5 --json >"$tmp/s.json"
check "... and the same numbers as beside its table" python3 -c 'import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); assert a["mass_kg"] == b["mass_kg"] and a["A_kg_m2"] == b["A_kg_m2"], (a, b)' "$tmp/l.json" "$tmp/s.json"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d["materials"]="mine.json"; json.dump(d, open(sys.argv[2], "w"))' designs/m12-setscrew.json "$tmp/lonely/named.json"
expect_fail "a design whose named table is missing" 2 "$tmp/lonely/mine.json" "does not exist" \
    "copy designs/materials.json there" -- materials "$tmp/lonely/named.json"
expect_fail "eval of a design whose named table is missing names the field" 2 "materials" "mine.json" -- eval "$tmp/lonely/named.json" --z2 5
expect_fail "a table that does not exist" 2 "cannot open" -- materials "$tmp/none.json"
printf '{"goo": {"density_g_cm3": -1, "source": "x", "printable": false}}\n' >"$tmp/bad.json"
expect_fail "a bad density" 2 "goo.density_g_cm3" "must be positive" -- materials "$tmp/bad.json"
check "materials --help exits 0" exits 0 materials --help
finish
