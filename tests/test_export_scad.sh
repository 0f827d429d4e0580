#!/usr/bin/env bash
# The OpenSCAD source tippe export writes renders, as written, for every
# shipped design in each of its show modes (issue 19.4: a part named
# 'weight' made the module weight() call itself); part names that are
# OpenSCAD built-ins, the file's own module names, names that differ only in
# punctuation and a name with a newline neither clash nor inject code; --split
# is in the source and its halves are the whole. And a printed part whose
# density is given inline is printed by export as eval models it (issue 19.8).
# Usage: test_export_scad.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
checker="$(pwd)/tests/export_check.py"

# --- 19.8: a print block with an inline density is printed (no OpenSCAD needed)
cp designs/materials.json "$tmp/"
json_edit designs/m12-setscrew-printed.json "$tmp/inline.json" \
    'del d["parts"][0]["material"]; d["parts"][0]["density_g_cm3"] = 1.08'
"$tippe" export designs/m12-setscrew-printed.json -o "$tmp/named" --format stl --json >"$tmp/named.json" 2>/dev/null
if "$tippe" export "$tmp/inline.json" -o "$tmp/inline" --format stl --json >"$tmp/inline.json.out" 2>"$tmp/inline.err"; then
    ok
    # the same solid as with the named material of that density: same body, same volume
    "$py" - "$tmp/named.json" "$tmp/inline.json.out" <<'EOF' && ok || bad "inline-density printed body differs from the named material's"
import json, sys
a = json.load(open(sys.argv[1]))["bodies"]; b = json.load(open(sys.argv[2]))["bodies"]
assert [x["name"] for x in a] == [x["name"] for x in b] == ["body"], (a, b)
assert abs(a[0]["exact_volume_mm3"] - b[0]["exact_volume_mm3"]) < 1e-9 * a[0]["exact_volume_mm3"]
EOF
else
    bad "a printed part with an inline density: export refused it: $(cat "$tmp/inline.err")"
fi
"$tippe" eval "$tmp/inline.json" --z2 5 --json >"$tmp/eval.json" 2>/dev/null
check "eval models the inline-density part as printed and lists the body export writes" \
    json_ok "$tmp/eval.json" 'o["printed_parts"] and [b["name"] for b in o["printed_bodies"]] == ["body"]'
# a part with an inline density and no print block stays hardware
json_edit designs/m12-setscrew.json "$tmp/inline-solid.json" \
    'del d["parts"][0]["material"]; d["parts"][0]["density_g_cm3"] = 1.08'
expect_fail "an inline density without a print block is not printed" 2 "nothing to print" -- \
    export "$tmp/inline-solid.json" -o "$tmp/inline-solid"

# --- issue 37: OpenSCAD's customizer annotations (its manual, "Customizer"): before the
# first module, tabs (/* [Display] */, the sphere, a tab per part, Hidden), each number
# outside Hidden with a [min:step:max] range that holds its value, show with its list
for args in "designs/m12-setscrew.json" "designs/shell-rod-nylon-printed.json --split"; do
    # shellcheck disable=SC2086
    "$tippe" export $args -o "$tmp/cust" --format scad >/dev/null 2>&1
    scad=$(ls "$tmp"/cust/*.scad)
    check "customizer annotations: $args" "$py" - "$scad" <<'EOF'
import re, sys
text = open(sys.argv[1]).read().split("\nmodule ")[0]
tab, seen, bad = None, [], []
for line in text.splitlines():
    m = re.match(r"/\* \[(.+)\] \*/$", line)
    if m:
        tab = m.group(1)
        seen.append(tab)
        continue
    m = re.match(r"^([A-Za-z_$][\w$]*) = ([^;]+);(?: // (.*))?$", line)
    if not m or tab == "Hidden":
        continue
    name, value, note = m.groups()
    if name == "show":
        ok = note in ("[all, printed]", "[all, printed, halves]")
    else:
        r = re.match(r"\[(-?[\d.e+-]+):([\d.e+-]+):(-?[\d.e+-]+)\]$", note or "")
        ok = tab is not None and r is not None and \
            float(r.group(1)) <= float(value) <= float(r.group(3))
    if not ok:
        bad.append(line)
assert seen[:2] == ["Display", "The sphere and the weight"] and seen[-1] == "Hidden" and \
    any(t.startswith("Part 1") for t in seen), seen
assert not bad, bad
EOF
    rm -rf "$tmp/cust"
done

command -v openscad >/dev/null || skip "openscad not on PATH: the OpenSCAD render checks are skipped (Debian package openscad)"
"$py" -c "import stl" 2>/dev/null || skip "numpy-stl (Debian python3-stl) is not installed"

# render SCAD SHOW OUT.stl: OpenSCAD renders SCAD with show = SHOW at 16 facets
# (the check is that it renders, and its volumes; 16 keeps CGAL quick).
render() {
    openscad -q -D "show=\"$2\"" -D fn=16 -o "$3" "$1" 2>"$3.err" && [ -s "$3" ]
}
vol() { "$py" "$checker" stl "$1" 2>/dev/null | "$py" -c 'import json,sys; print(json.load(sys.stdin)["volume_mm3"])'; }

# --- every shipped design, every show mode; --split in the source of each ---
for f in designs/*.json; do
    "$py" -c 'import json,sys; sys.exit(0 if "parts" in json.load(open(sys.argv[1])) else 1)' "$f" || continue
    stem=$(basename "$f" .json)
    "$tippe" export "$f" -o "$tmp/$stem" --format scad >/dev/null 2>&1 || { bad "$stem: export"; continue; }
    for show in all printed; do
        render "$tmp/$stem/$stem.scad" $show "$tmp/$stem-$show.stl" && ok ||
            bad "$stem: show=$show does not render: $(head -c 300 "$tmp/$stem-$show.stl.err")"
    done
    "$tippe" export "$f" -o "$tmp/$stem-split" --format scad --split >/dev/null 2>&1 || { bad "$stem --split: export"; continue; }
    s=$tmp/$stem-split/$stem.scad
    check "$stem --split: the cut plane is in the OpenSCAD source" grep -q '^split_z_mm = 0;' "$s"
    # the halves rendered for one design of each kind (ball with a through or
    # a blind hole, shell with a band, with a rod through it): CI time
    case $stem in m12-setscrew | drilled-ball-blind | shell-band | shell-rod-through-printed) ;; *) continue ;; esac
    for show in all printed halves; do
        render "$s" $show "$tmp/$stem-split-$show.stl" && ok ||
            bad "$stem --split: show=$show does not render: $(head -c 300 "$tmp/$stem-split-$show.stl.err")"
    done
done

# --- the halves are the whole: same facets, the cut adds no volume ----------
# (CGAL is exact on the 16-gon: only float output rounding, ~1e-7 relative)
for stem in m12-setscrew shell-band; do
    whole=$(vol "$tmp/$stem-split-printed.stl") halves=$(vol "$tmp/$stem-split-halves.stl")
    check "$stem: halves $halves mm^3 = whole $whole mm^3" \
        "$py" -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if a > 0 and abs(a - b) < 1e-5 * a else 1)" "$whole" "$halves"
done

# --- --joint in the source: the halves lose the grooves, the ring fills them --
# All in OpenSCAD's own 16-gons (area 8 r^2 sin(pi/8)), exact in CGAL: the
# halves laid out with the ring = the printed body - the grooves (2 h deep, the
# hole's 16-gon r 5.7 to the wall's middle m) + the ring (2 h - c high, r 5.7 to m - c).
"$tippe" export designs/m12-setscrew.json -o "$tmp/joint" --format scad --split --joint >/dev/null 2>&1
render "$tmp/joint/m12-setscrew.scad" halves "$tmp/joint-halves.stl" && ok || bad "--joint: show=halves does not render"
p=$(vol "$tmp/m12-setscrew-split-printed.stl") j=$(vol "$tmp/joint-halves.stl")
check "--joint: halves + ring $j mm^3 = printed $p mm^3 - grooves + ring (16-gons)" \
    "$py" -c "
import math, sys
p, j = map(float, sys.argv[1:])
A = lambda r: 8 * r * r * math.sin(math.pi / 8)
a, m, h, c = 5.7, (5.7 + 25) / 2, 2.0, 0.2
want = p - 2 * h * (A(m) - A(a)) + (2 * h - c) * (A(m - c) - A(a))
sys.exit(0 if abs(j - want) < 1e-5 * p else 1)" "$p" "$j"

# --- names that clashed or injected ------------------------------------------
# shell-band's parts renamed: an OpenSCAD built-in, the file's own module
# names, two names that differ only in punctuation (both kept apart), and a
# name that closes a string, a comment and a module and adds a 100 mm cube. (A name
# with a newline is refused when the design is read, issue 28.2: checked below.)
json_edit designs/shell-band.json "$tmp/newline.json" '
d["parts"][3]["name"] = "weight\n}\ncube(100);\nmodule x() {"
'
expect_fail "a part name with a newline is refused at load" 2 "parts[3].name" -- \
    export "$tmp/newline.json" -o "$tmp/newline" --format scad
json_edit designs/shell-band.json "$tmp/names.json" '
names = ["printed", "cylinder", "a b", "weight\"; */ } cube(100); module x() { /*"]
for p, n in zip(d["parts"], names): p["name"] = n
d["parts"].insert(2, {"name": "a_b", "shape": "ball", "radius_mm": 1, "z_mm": 23.5, "void": True, "cut_from": "printed"})
'
"$tippe" export "$tmp/names.json" -o "$tmp/names" --format scad >/dev/null 2>"$tmp/names.err" ||
    bad "renamed parts: export: $(cat "$tmp/names.err")"
for show in all printed; do
    render "$tmp/names/names.scad" $show "$tmp/names-$show.stl" && ok ||
        bad "renamed parts: show=$show does not render: $(head -c 300 "$tmp/names-$show.stl.err")"
done
# the printed volume is shell-band's less the 1 mm ball cut from the shell's
# wall at the pole (at 16 facets each:
# OpenSCAD's own 16-gon sphere volume, measured from a render of the ball alone)
printf 'sphere(r = 1, $fn = 16);\n' >"$tmp/ball.scad"
openscad -q -o "$tmp/ball.stl" "$tmp/ball.scad" 2>/dev/null
a=$(vol "$tmp/shell-band-printed.stl") b=$(vol "$tmp/names-printed.stl") c=$(vol "$tmp/ball.stl")
check "renamed parts: printed volume $b = shell-band's $a - the ball's $c (no cube injected, no part lost)" \
    "$py" -c "import sys; a, b, c = map(float, sys.argv[1:]); sys.exit(0 if abs(a - c - b) < 1e-5 * a else 1)" "$a" "$b" "$c"
# the 'all' render holds every part, the bead whatever it is called
a=$(vol "$tmp/shell-band-all.stl") b=$(vol "$tmp/names-all.stl")
check "renamed parts: show=all volume $b = shell-band's $a - the ball's $c" \
    "$py" -c "import sys; a, b, c = map(float, sys.argv[1:]); sys.exit(0 if abs(a - c - b) < 1e-5 * a else 1)" "$a" "$b" "$c"
finish
