#!/usr/bin/env bash
# From optimise to build (issue 25.3): a BEST.json whose weight is a catalogue
# item names the item ("catalogue_item") and the catalogue ("catalogue",
# rebased from the output's folder as "materials" is), so that tippe build of
# it names the set screw without --catalogue; the design loader's checks of
# both keys, and tippe build's of the item against the catalogue.
# Usage: test_catalogue_item.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
repo=$(pwd)
tippe_abs=$(cd "$(dirname "$tippe")" && pwd)/$(basename "$tippe")

# --- a small catalogue search, written two folders away from the catalogue ---
python3 - "$repo" "$tmp/spec.json" <<'EOF'
import json, sys
repo, out = sys.argv[1], sys.argv[2]
s = json.load(open(repo + "/designs/optimise/drilled-ball-catalogue.json"))
s["design"] = repo + "/designs/drilled-ball-blind.json"
s["catalogue"] = repo + "/designs/catalogue.json"
s["choose"] = {"parts.screw": {"catalogue": "iso4026", "items": ["M12x12", "M10x12"]},
               "parts.screw.material": ["iron"]}
s["search"] = {"algorithm": "DIRECT-L", "evaluations": 10, "polish": "none"}
json.dump(s, open(out, "w"))
EOF
mkdir -p "$tmp/a/b"
check "optimise writes BEST.json" "$tippe" optimise "$tmp/spec.json" -o "$tmp/a/b/best.json" --json >"$tmp/res.json" 2>"$tmp/opt.err"
python3 - "$tmp/a/b/best.json" "$repo/designs/catalogue.json" "$tmp/res.json" <<'EOF' && ok || bad "BEST.json lacks the item or the rebased catalogue"
import json, os, sys
d = json.load(open(sys.argv[1]))
screw = [p for p in d["parts"] if p["name"] == "screw"][0]
assert screw["catalogue_item"] in ("M12x12", "M10x12"), screw
assert "this one " + screw["catalogue_item"] in d["notes"], d["notes"]
assert not os.path.isabs(d["catalogue"]), d["catalogue"]
here = os.path.dirname(os.path.realpath(sys.argv[1]))
assert os.path.realpath(os.path.join(here, d["catalogue"])) == os.path.realpath(sys.argv[2]), d["catalogue"]
print(screw["catalogue_item"], file=open(sys.argv[1] + ".item", "w"))
EOF
item=$(cat "$tmp/a/b/best.json.item" 2>/dev/null)
check "no catalogue.json beside BEST.json" test ! -e "$tmp/a/b/catalogue.json"
# --- tippe build of it names the screw, from the catalogue it names -----------
(cd "$tmp" && "$tippe_abs" build a/b/best.json -o sheet --no-export --json) >"$tmp/b.json" 2>"$tmp/b.err"
check "build of BEST.json names the catalogue item $item" \
    json_ok "$tmp/b.json" 'o["thread"]["catalogue_item"] == "'"$item"'" and not o["thread"]["assumed"] and any(b["item"].startswith("set screw " + o["thread"]["catalogue_item"] + " (") and "ISO 4026" in b["item"] for b in o["bill_of_materials"])'
(cd "$tmp" && "$tippe_abs" build a/b/best.json -o sheet2 --no-export) >"$tmp/b.md" 2>&1
check "the Markdown's bill says set screw $item ... ISO 4026" grep -q "| 1 | set screw $item (.*ISO 4026" "$tmp/b.md"

# --- the loader's checks -------------------------------------------------------
b=$tmp/a/b/best.json
json_edit "$b" "$tmp/a/b/empty.json" 'd["catalogue"] = ""'
expect_fail "an empty catalogue" 2 "catalogue" "must be a file name" -- eval "$tmp/a/b/empty.json" --z2 5
json_edit "$b" "$tmp/a/b/missing.json" 'd["catalogue"] = "nowhere.json"'
expect_fail "a catalogue that is not there" 2 "catalogue" "nowhere.json" "cannot be read" -- eval "$tmp/a/b/missing.json" --z2 5
json_edit "$b" "$tmp/a/b/number.json" 'd["catalogue"] = 3'
expect_fail "a catalogue that is a number" 2 "catalogue" -- eval "$tmp/a/b/number.json" --z2 5
json_edit "$b" "$tmp/a/b/void.json" '[p for p in d["parts"] if p["name"] == "hole"][0]["catalogue_item"] = "M12x12"'
expect_fail "a catalogue item on a void" 2 "catalogue_item" "void" -- eval "$tmp/a/b/void.json" --z2 5
json_edit "$b" "$tmp/a/b/noname.json" '[p for p in d["parts"] if p["name"] == "screw"][0]["catalogue_item"] = ""'
expect_fail "an empty catalogue item" 2 "catalogue_item" "must not be empty" -- eval "$tmp/a/b/noname.json" --z2 5
expect_fail "an unknown part key is still refused" 2 "catalogue_itm" -- \
    eval "$b" --z2 5 --set parts.screw.catalogue_itm=M12x12
check "eval reads BEST.json" exits 0 eval "$b" --z2 5
# --- the build's checks of the item --------------------------------------------
expect_fail "an item the catalogue lacks" 2 "catalogue_item" "'M99x1' is not an item" -- \
    build "$b" -o "$tmp/x1" --no-export --set parts.screw.catalogue_item=M99x1
expect_fail "an item of another length than the part" 2 "catalogue_item" "long" -- \
    build "$b" -o "$tmp/x2" --no-export --set parts.screw.height_mm=11
check "no directory left by a refused build" test ! -e "$tmp/x1" -a ! -e "$tmp/x2"
"$tippe" build "$b" -o "$tmp/x3" --no-export --json --set parts.screw.height_mm=11 \
    --set parts.screw.catalogue_item=null >"$tmp/x3.json" 2>/dev/null
check "catalogue_item=null: matched by size again (none is 11 mm long)" \
    json_ok "$tmp/x3.json" 'o["thread"]["catalogue_item"] is None and o["thread"]["assumed"]'
json_edit "$b" "$tmp/a/b/nocat.json" 'del d["catalogue"]'
expect_fail "an item without a catalogue" 2 "catalogue_item" "no catalogue is given" -- \
    build "$tmp/a/b/nocat.json" -o "$tmp/x4" --no-export
"$tippe" build "$tmp/a/b/nocat.json" -o "$tmp/x5" --no-export --json \
    --catalogue designs/catalogue.json >"$tmp/x5.json" 2>/dev/null
check "--catalogue gives it" json_ok "$tmp/x5.json" 'o["thread"]["catalogue_item"] == "'"$item"'"'
finish
