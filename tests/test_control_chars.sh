#!/usr/bin/env bash
# Control characters in names and notes (issue 28, item 2): U+0001, U+0007,
# ESC [2J, CR LF, a C1 control (U+009B, a terminal's CSI) and bytes that are not
# UTF-8 are refused when a file is read, with exit 2, the file and the field
# named, and never echoed raw to the terminal. Names and labels (the design's
# name, part names, material names, a scenario's name) are one line of
# printable text; notes are free text, where a line break (\n) and a tab (\t)
# are allowed and every other control (CR, ESC, ...) is not. A catalogue's item
# names are checked in test_catalogue.sh. Usage: test_control_chars.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
cp designs/materials.json "$tmp/"
mk=designs/m12-setscrew.json

# edit OUT FIELD VALUE_PY: the M12 design with FIELD set to the python string VALUE_PY.
edit() {
    python3 - "$mk" "$1" "$2" "$3" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
field, value = sys.argv[3], eval(sys.argv[4])
if field == "part":
    d["parts"][0]["name"] = value
    d["parts"][1]["cut_from"] = value
elif field == "part_notes":
    d["parts"][1]["notes"] = value
else:
    d[field] = value
json.dump(d, open(sys.argv[2], "w"))
EOF
}
# raw_free FILE: no control character but \n in FILE (stderr with the message).
raw_free() { ! LC_ALL=C grep -q $'[\x01-\x09\x0b-\x1f\x7f]' "$1"; }

# name: the python literal of the text; what the message must say of the field.
controls=('"\x01"' '"\x07"' '"\x1b[2J"' '"\r\n"' '"\x9b"' '"\x7f"')
for c in "${controls[@]}"; do
    for field in name part; do
        f=$tmp/c.json
        edit "$f" "$field" "\"a\" + $c + \"b\""
        path=name
        [ "$field" = part ] && path='parts[0].name'
        expect_fail "$field with $c is refused" 2 "$f: $path: character 2 is the control character" -- eval "$f" --z2 5
        check "$field with $c: the message carries no raw control" raw_free "$tmp/err"
    done
    for field in notes part_notes; do
        f=$tmp/c.json
        edit "$f" "$field" "\"one line\" + $c + \"two\""
        path=notes
        [ "$field" = part_notes ] && path='parts[1].notes'
        expect_fail "$field with $c is refused" 2 "$f: $path: character 9 is the control character" \
            "free text may hold line breaks" -- eval "$f" --z2 5
    done
done

# Notes are free text: a line break and a tab are fine.
edit "$tmp/nl.json" notes '"first line\nsecond line\twith a tab"'
check "notes with a line break and a tab are accepted" exits 0 eval "$tmp/nl.json" --z2 5
edit "$tmp/nl.json" part_notes '"first line\nsecond"'
check "part notes with a line break are accepted" exits 0 eval "$tmp/nl.json" --z2 5
# ... but never in a name.
edit "$tmp/c.json" name '"two\nlines"'
expect_fail "a name with a line break is refused" 2 "$tmp/c.json: name: character 4 is the control character U+000A" -- eval "$tmp/c.json" --z2 5
# Not UTF-8.
python3 -c 'import sys; open(sys.argv[1], "wb").write(open(sys.argv[2], "rb").read().replace(b"M12 setscrew", b"M12 \xff\xfe"))' "$tmp/u.json" "$mk"
expect_fail "a name that is not UTF-8 is refused" 2 "$tmp/u.json: name: character 5 is not valid UTF-8 (byte 0xFF)" -- eval "$tmp/u.json" --z2 5
# Printable non-ASCII text is fine.
edit "$tmp/ok.json" name '"Kreisel \u00e9t\u00e9 \u2014 \u72ec\u697d"'
check "a name in UTF-8 beyond ASCII is accepted" exits 0 eval "$tmp/ok.json" --z2 5

# An override is checked as the file is, and echoed without its controls.
expect_fail "--set name=ESC[2J is refused" 2 "name: character 2 is the control character U+001B" \
    '(set by --set name=a\x1B[2J)' -- eval "$mk" --z2 5 --set "name=a"$'\e'"[2J"
check "--set name=ESC: the message carries no raw control" raw_free "$tmp/err"

# Materials: a material's name (its key) and its notes.
python3 - designs/materials.json "$tmp/m-name/materials.json" "$tmp/m-notes/materials.json" <<'EOF'
import json, os, sys
t = json.load(open(sys.argv[1]))
for out in sys.argv[2:]:
    os.makedirs(os.path.dirname(out))
t2 = dict(t)
t2["bad\x1b[2Jname"] = dict(t["iron"])
json.dump(t2, open(sys.argv[2], "w"))
t3 = dict(t)
t3["iron"] = dict(t["iron"], notes="x\x07y")
json.dump(t3, open(sys.argv[3], "w"))
EOF
cp "$mk" "$tmp/m-name/d.json"
cp "$mk" "$tmp/m-notes/d.json"
expect_fail "a material named with ESC is refused" 2 "$tmp/m-name/materials.json: bad\\x1B[2Jname: character 4 is the control character U+001B" -- eval "$tmp/m-name/d.json" --z2 5
check "the material's name is echoed without its controls" raw_free "$tmp/err"
expect_fail "a material's notes with BEL are refused" 2 "$tmp/m-notes/materials.json: iron.notes: character 2 is the control character U+0007" -- materials "$tmp/m-notes/d.json"

# A scenario's name and notes.
python3 - designs/scenarios/fig12-tip.json "$tmp/s1.json" "$tmp/s2.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
json.dump(dict(s, name="fig\x1b[2J12", t_end=1), open(sys.argv[2], "w"))
json.dump(dict(s, notes="a\r\nb", t_end=1), open(sys.argv[3], "w"))
EOF
expect_fail "a scenario named with ESC is refused" 2 "$tmp/s1.json: name: character 4 is the control character U+001B" -- simulate "$tmp/s1.json"
expect_fail "a scenario's notes with CR are refused" 2 "$tmp/s2.json: notes: character 2 is the control character U+000D" -- simulate "$tmp/s2.json"
finish
