#!/usr/bin/env bash
# The hardware catalogue is read as strictly as a design (issue 28, item 3): a
# thread that cannot be made (pitch 50, 0, negative, 1e-300, 1e308 mm; d 0 or
# 1e308 mm; a "thread" that is not d_mm's), a mistyped or missing field, null
# items, "items" an object, a repeated item name, an unknown key, a control
# character in a name: each refused by tippe build with exit 2, the file, the
# JSON path and what is wrong, the "(try tippe build --help)" hint, before any
# work (no output directory made). tippe optimise reads a spec's catalogue the
# same way. Usage: test_catalogue.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/drilled-ball-catalogue-best.json # its screw is the catalogue's M10x12

# mkcat NAME PYTHON: $tmp/NAME.json, the shipped catalogue after PYTHON changed c
# (it: the item M10x12, the one the design's screw matches).
mkcat() {
    python3 - designs/catalogue.json "$tmp/$1.json" "$2" <<'EOF'
import json, sys
c = json.load(open(sys.argv[1]))
it = [i for i in c["iso4026"]["items"] if i["name"] == "M10x12"][0]
exec(sys.argv[3])
open(sys.argv[2], "w").write(json.dumps(c, indent=1) if not isinstance(c, str) else c)
EOF
}
# refused NAME WHAT PATTERN...: build with catalogue NAME exits 2 naming the
# file, each PATTERN and the hint, and makes no output directory.
refused() {
    local name=$1 what=$2
    shift 2
    expect_fail "$what" 2 "$tmp/$name.json: " "$@" "(try tippe build --help)" -- \
        build "$d" -o "$tmp/out-$name" --catalogue "$tmp/$name.json"
    check "$what: no output directory made" test ! -e "$tmp/out-$name"
}
m=iso4026.items[42] # M10x12's place in the shipped catalogue

mkcat p50 'it["pitch_mm"] = 50'
refused p50 "pitch 50 mm on M10" "$m.pitch_mm: 50 mm is not the pitch of a thread of d_mm = 10 mm" "0.2 .. 2.5 mm here" "tap drill d - P would be -40 mm"
mkcat p0 'it["pitch_mm"] = 0'
refused p0 "pitch 0" "$m.pitch_mm: 0 mm is not the pitch"
mkcat pneg 'it["pitch_mm"] = -1.5'
refused pneg "negative pitch" "$m.pitch_mm: -1.5 mm is not the pitch"
mkcat ptiny 'it["pitch_mm"] = 1e-300'
refused ptiny "pitch 1e-300 mm" "$m.pitch_mm: 1e-300 mm is not the pitch"
mkcat pbig 'it["pitch_mm"] = 1e308'
refused pbig "pitch 1e308 mm" "$m.pitch_mm: 1e+308 mm is not the pitch"
mkcat p3 'it["pitch_mm"] = 3'
refused p3 "pitch 3 mm on M10 (above d/4)" "$m.pitch_mm: 3 mm is not the pitch" "at most a quarter of the diameter"
mkcat d0 'it["d_mm"] = 0'
refused d0 "d 0" "$m.d_mm: 0 mm is not a metric thread's diameter (ISO 261: 1 .. 300 mm)"
mkcat dbig 'it["d_mm"] = 1e308'
refused dbig "d 1e308 mm" "$m.d_mm: 1e+308 mm is not a metric thread's diameter"
mkcat dthread 'it["d_mm"] = 12'
refused dthread "thread M10 with d 12 mm" "$m.thread: 'M10' is not the thread of d_mm = 12 mm"
mkcat rwide 'it["radius_mm"] = 6'
refused rwide "a screw wider than its thread" "$m.radius_mm: 6 mm is wider than the thread"
mkcat hneg 'it["height_mm"] = -12'
refused hneg "negative height" "$m.height_mm: must be positive"
mkcat pstr 'it["pitch_mm"] = "1.5"'
refused pstr "a string pitch" "$m.pitch_mm: must be a number, not a string"
mkcat pmiss 'del it["pitch_mm"]'
refused pmiss "a missing pitch" "$m.pitch_mm: missing (a number is required)"
mkcat pnull 'it["pitch_mm"] = None'
refused pnull "a null pitch" "$m.pitch_mm: must be a number, not null"
mkcat nullitem 'c["iso4026"]["items"].append(None)'
refused nullitem "a null item" "iso4026.items[62]: must be an object (a catalogue item), not null"
mkcat nullitems 'c["iso4026"]["items"] = None'
refused nullitems "items null" "iso4026.items: must be an array of items, not null"
mkcat itemsobj 'c["iso4026"]["items"] = {"M10x12": it}'
refused itemsobj "items an object" "iso4026.items: must be an array of items, not an object"
mkcat noitems 'c["iso4026"]["items"] = []'
refused noitems "no items" "iso4026.items: must hold at least one item"
mkcat dupname 'c["iso4026"]["items"].append(dict(it))'
refused dupname "a repeated item name" "iso4026.items[62].name: 'M10x12' is already the name of iso4026.items[42]"
mkcat unknown 'it["colour"] = "red"'
refused unknown "an unknown item key" "$m.colour: unknown field (a catalogue item has: name,"
mkcat unknownset 'c["iso4026"]["vendor"] = "x"'
refused unknownset "an unknown catalogue key" "iso4026.vendor: unknown field (a catalogue has: title, source, notes, items)"
mkcat dupkey 'c = json.dumps(c).replace("\"pitch_mm\": 1.5, \"length_mm\": 12", "\"pitch_mm\": 1.5, \"pitch_mm\": 1.25, \"length_mm\": 12", 1)'
refused dupkey "a repeated key" "pitch_mm: duplicate key"
mkcat emptyname 'it["name"] = ""'
refused emptyname "an empty item name" "$m.name: must not be empty"
mkcat esc 'it["name"] = "M10\x1b[2Jx12"'
refused esc "an item name with ESC" "$m.name: character 4 is the control character U+001B"
mkcat titlecr 'c["iso4026"]["title"] = "ISO\r\n4026"'
refused titlecr "a title with CR LF" "iso4026.title: character 4 is the control character U+000D"
mkcat array 'c = [c]'
refused array "a list instead of an object" "must be an object of named catalogues, not an array"
mkcat empty 'c = {}'
refused empty "no catalogue at all" "holds no catalogue"

# the shipped catalogue is accepted and its item matched
"$tippe" build "$d" -o "$tmp/good" --no-export --json --catalogue designs/catalogue.json >"$tmp/good.json" 2>"$tmp/err"
check "the shipped catalogue is accepted ($(cat "$tmp/err"))" \
    json_ok "$tmp/good.json" 'o["thread"]["catalogue_item"] == "M10x12"'
# a fine thread within the rules (M10 x 1.25) is accepted and used
mkcat fine 'it["pitch_mm"] = 1.25'
"$tippe" build "$d" -o "$tmp/fine" --no-export --json --catalogue "$tmp/fine.json" >"$tmp/fine.out" 2>"$tmp/err"
check "a fine pitch (M10 x 1.25) is accepted and used ($(cat "$tmp/err"))" \
    json_ok "$tmp/fine.out" 'o["thread"]["catalogue_item"] == "M10x12" and abs(o["thread"]["pitch_mm"] - 1.25) < 1e-12'

# tippe optimise reads a spec's catalogue the same way (refused before any search)
mkdir -p "$tmp/opt/optimise"
cp designs/drilled-ball-blind.json designs/materials.json "$tmp/opt/"
cp designs/optimise/drilled-ball-catalogue.json "$tmp/opt/optimise/"
cp "$tmp/p50.json" "$tmp/opt/catalogue.json"
expect_fail "optimise: a catalogue with pitch 50 mm is refused" 2 \
    "$tmp/opt/optimise/../catalogue.json: $m.pitch_mm: 50 mm is not the pitch" -- \
    optimise "$tmp/opt/optimise/drilled-ball-catalogue.json" -o "$tmp/best.json"
# issue 37: a set screw written as design-format.md writes one (its radius the hole's, the
# thread's nominal d/2) is the catalogue's item of that thread and length: the M3 (1.5 mm,
# 3 mm) is M3x3, modelled at its pitch radius 1.3376 mm; a length outside js15 of every
# item's (2.5 mm: the shortest, M3x3, is within +/-0.2 mm) is none
"$tippe" build designs/m3-setscrew.json -o "$tmp/m3" --no-export --json >"$tmp/m3.json" 2>/dev/null
check "the M3 (radius 1.5 = d/2, 3 mm) is matched to M3x3, its thread not assumed" \
    json_ok "$tmp/m3.json" 'o["thread"]["catalogue_item"] == "M3x3" and not o["thread"]["assumed"] and o["thread"]["pitch_mm"] == 0.5'
"$tippe" build designs/m3-setscrew.json --set parts.screw.height_mm=2.5 -o "$tmp/m3b" --no-export \
    --json >"$tmp/m3b.json" 2>/dev/null
check "an M3 2.5 mm long (no item within js15) is matched to none" \
    json_ok "$tmp/m3b.json" 'o["thread"]["catalogue_item"] in (None, "") and o["thread"]["assumed"]'
finish
