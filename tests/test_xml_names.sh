#!/usr/bin/env bash
# Names with XML's and Markdown's markup in them (issue 28, item 1): a design
# named "Ball & screw" (or with '<', ']]>', '<!--', quotes) and a part named so
# are exported and built; every XML file of the 3MF (the model, the slicer's
# config, the package parts) and every SVG is parsed by a strict XML parser
# (python's expat), and the 3MF's Title and object names read back as the names
# given; the build sheet's Markdown keeps its tables whole.
# Usage: test_xml_names.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

# xml_ok FILE.3mf NAME PART: every XML entry well-formed, Title == NAME, an object named PART.
xml_ok() {
    python3 - "$@" <<'EOF'
import sys, zipfile, xml.etree.ElementTree as ET
path, name, part = sys.argv[1:4]
z = zipfile.ZipFile(path)
ns = "{http://schemas.microsoft.com/3dmanufacturing/core/2015/02}"
title = objects = None
for n in z.namelist():
    if n.endswith((".model", ".config", ".rels", ".xml")):
        try:
            root = ET.fromstring(z.read(n))
        except ET.ParseError as e:
            sys.exit("%s: %s is not well-formed XML: %s" % (path, n, e))
        if n.endswith(".model"):
            title = [m.text for m in root.iter(ns + "metadata") if m.get("name") == "Title"]
            objects = [o.get("name") for o in root.iter(ns + "object")]
if title != [name]:
    sys.exit("%s: Title %r, want %r" % (path, title, name))
if part not in objects:
    sys.exit("%s: objects %r, want one named %r" % (path, objects, part))
EOF
}
# svg_ok FILE...: each parses.
svg_ok() {
    python3 -c '
import sys, xml.etree.ElementTree as ET
for f in sys.argv[1:]:
    ET.parse(f)' "$@"
}
# md_ok FILE.md: every table row has as many unescaped "|" as its header.
md_ok() {
    python3 - "$1" <<'EOF'
import re, sys
cols = None
for line in open(sys.argv[1]):
    if not line.startswith("|"):
        cols = None
        continue
    n = len(re.findall(r"(?<!\\)\|", line))
    if cols is None:
        cols = n
    elif n != cols:
        sys.exit("%s: a table row has %d cells' bars, its header %d: %s" % (sys.argv[1], n, cols, line))
EOF
}

names=('Ball & screw' 'a <b> c' 'x ]]> y' 'p <!-- q' "q\"uo'te & <tag/>" 'M&M | [x](y) `z`')
parts=('body & co' 'b<o>dy' 'bo]]>dy' 'bo<!--dy' "b\"o'dy" 'b|o')
for i in "${!names[@]}"; do
    name=${names[$i]} part=${parts[$i]}
    f=$tmp/odd$i.json
    NAME=$name PART=$part python3 - designs/m12-setscrew.json "$f" <<'EOF'
import json, os, sys
d = json.load(open(sys.argv[1]))
d["name"] = os.environ["NAME"]
d["parts"][0]["name"] = os.environ["PART"]
d["parts"][1]["cut_from"] = os.environ["PART"]
json.dump(d, open(sys.argv[2], "w"))
EOF
    cp designs/materials.json designs/catalogue.json "$tmp/"
    "$tippe" export "$f" -o "$tmp/e$i" >/dev/null 2>"$tmp/err"
    check "export of a design named '$name' exits 0 ($(cat "$tmp/err"))" test $? -eq 0 || continue
    check "export '$name': the 3MF's XML is well-formed and holds the names" \
        xml_ok "$tmp/e$i/odd$i.3mf" "$name" "$part"
    check "export '$name': the section SVG is well-formed" svg_ok "$tmp/e$i/odd$i-section.svg"
    "$tippe" build "$f" -o "$tmp/b$i" >/dev/null 2>"$tmp/err"
    check "build of a design named '$name' exits 0 ($(cat "$tmp/err"))" test $? -eq 0 || continue
    check "build '$name': the 3MF's XML is well-formed and holds the names" \
        xml_ok "$tmp/b$i/odd$i.3mf" "$name" "$part"
    check "build '$name': the SVGs are well-formed" svg_ok "$tmp/b$i"/*.svg
    check "build '$name': the Markdown sheet's tables keep their columns" md_ok "$tmp/b$i/odd$i-build.md"
    check "build '$name': the Markdown heading escapes the name's markup" \
        test "$(head -1 "$tmp/b$i/odd$i-build.md" | sed 's/\\\(.\)/\1/g')" = "# Build sheet: $name"
done
finish
