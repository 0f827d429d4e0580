#!/usr/bin/env bash
# Sockets for a rod that spans a shell's cavity (tippe export --split --sockets,
# and tippe build, which exports so): where they are and what they remove,
# against the closed form computed here from the design file alone; the rod of
# the bill of materials is cut to sit in them and the bead's depth is measured
# from its real end; a rod through the shell's holes gets none; refusals.
# Usage: test_rod_sockets.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

d=designs/shell-rod-nylon-printed.json
"$tippe" export $d -o "$tmp/s1" --split --sockets --format stl,scad --json >"$tmp/s1.json" 2>"$tmp/err" ||
    bad "export --split --sockets failed: $(cat "$tmp/err")"
"$tippe" export $d -o "$tmp/s0" --split --format stl,scad --json >"$tmp/s0.json"
for h in lower upper; do
    /usr/bin/python3 tests/export_check.py stl "$tmp/s1/shell-rod-nylon-printed-shell-$h.stl" >"$tmp/$h.json" 2>/dev/null
done
python3 - "$tmp/s1.json" "$tmp/s0.json" $d "$tmp/lower.json" "$tmp/upper.json" <<'EOF' && ok || bad "the sockets' place and volume"
import json, math, sys
s1, s0, d, lo, hi = (json.load(open(f)) for f in sys.argv[1:])
p = {x["name"]: x for x in d["parts"]}
R = d["radius_mm"]
Rc = R - p["shell"]["thickness_mm"]                     # the rod is clipped to the cavity
a = p["rod"]["radius_mm"] + 0.2                         # the rod plus the default clearance
rim = math.sqrt(Rc * Rc - a * a)                        # the pocket's side meets the cavity
floor = rim + 1.0                                       # 1 mm into the wall
# the wall the pocket removes: the cylinder r <= a up to the floor less the
# cavity's cap over r <= a (shell method)
pocket = math.pi * a * a * floor - 2 * math.pi / 3 * (Rc ** 3 - (Rc * Rc - a * a) ** 1.5)
so = sorted(s1["sockets"], key=lambda x: x["floor_z_mm"])
assert len(so) == 2 and s0["sockets"] == [], (s1["sockets"], s0["sockets"])
for x, e in zip(so, (-1, 1)):
    assert x["rod"] == "rod" and abs(x["diameter_mm"] - 2 * a) < 1e-12
    assert abs(x["rim_z_mm"] - e * rim) < 1e-12 and abs(x["floor_z_mm"] - e * floor) < 1e-12
    assert abs(x["volume_mm3"] - pocket) < 1e-9 * pocket, (x["volume_mm3"], pocket)
# the profiles (within chord / 2 = 0.005 mm of the cavity's arc, which bounds
# the pocket over r <= a): the halves lose the two pockets to pi a^2 0.005 each
vol = lambda r: sum(b["profile_volume_mm3"] for b in r["bodies"])
lost = vol(s0) - vol(s1)
assert abs(lost - 2 * pocket) < 2 * math.pi * a * a * 0.005, (lost, 2 * pocket)
# the meshes read back: the shell less the pockets, within 0.1 % (the export bound)
shell = 4 / 3 * math.pi * (R ** 3 - Rc ** 3) - 2 * pocket
got = lo["volume_mm3"] + hi["volume_mm3"]
assert abs(got - shell) / shell < 1e-3, (got, shell)
for h in (lo, hi):
    assert h["open_edges"] == 0 and h["inconsistent_edges"] == 0 and h["degenerate_facets"] == 0
EOF
check "the OpenSCAD source cuts the sockets" grep -q "// socket$" "$tmp/s1/shell-rod-nylon-printed.scad"

# a rod through the shell's holes is held by them: no socket
"$tippe" export designs/shell-rod-through-printed.json -o "$tmp/t" --split --sockets --format stl --json >"$tmp/t.json"
check "a rod through the shell's holes gets no socket" json_ok "$tmp/t.json" 'o["sockets"] == []'

# --- build: the rod cut to sit in them, the bead measured from its real end ---
"$tippe" build $d -o "$tmp/b" --json >"$tmp/b.json" 2>"$tmp/err" || bad "build failed: $(cat "$tmp/err")"
python3 - "$tmp/b.json" $d <<'EOF' && ok || bad "build: the rod's length and the bead's depth"
import json, math, sys
b, d = (json.load(open(f)) for f in sys.argv[1:])
p = {x["name"]: x for x in d["parts"]}
Rc = d["radius_mm"] - p["shell"]["thickness_mm"]
floor = math.sqrt(Rc ** 2 - (p["rod"]["radius_mm"] + 0.2) ** 2) + 1.0
assert abs(b["measure"]["reference_z_mm"] - floor) < 1e-9 and "sockets" in b["measure"]["reference"]
h = p["weight"]["height_mm"]
for st in b["settings"]:
    if st["reachable"]:
        assert abs(st["depth_set_mm"] - (floor - (st["set_z2_mm"] + h / 2))) < 1e-9
rod = [x for x in b["bill_of_materials"] if "rod 'rod'" in x["item"]]
assert len(rod) == 1 and "length %.2f mm" % (2 * floor) in rod[0]["detail"] and "sockets" in rod[0]["detail"], rod
assert any("socket" in s for s in b["steps"]) and any("sockets" in n for n in b["notes"])
EOF
check "build writes the halves with the sockets (the .scad cuts them)" \
    grep -q "// socket$" "$tmp/b/shell-rod-nylon-printed.scad"
# the drawing dimensions what is bought and cut: the rod's length to the
# sockets' floors, the socket, the bead's bore
/usr/bin/python3 tests/export_check.py svg "$tmp/b/shell-rod-nylon-printed-section.svg" >"$tmp/svg.json"
python3 - "$tmp/svg.json" $d <<'EOF' && ok || bad "the drawing's rod length, socket and bore"
import json, math, sys
s, d = (json.load(open(f)) for f in sys.argv[1:])
p = {x["name"]: x for x in d["parts"]}
Rc = d["radius_mm"] - p["shell"]["thickness_mm"]
a = p["rod"]["radius_mm"] + 0.2
floor = math.sqrt(Rc ** 2 - a ** 2) + 1.0
got = {x["name"]: x["mm"] for x in s["dims"]}
want = {"rod.length_mm": 2 * floor, "rod.socket_diameter_mm": 2 * a,
        "weight bore.diameter_mm": 2 * p["weight"]["inner_radius_mm"]}
for k, v in want.items():
    # the SVG states values to 10 significant digits: 1e-6 mm is ample
    assert k in got and abs(got[k] - v) < 1e-6, (k, got.get(k), v)
EOF

# --- the OpenSCAD source renders with them and its printed part loses volume --
if command -v openscad >/dev/null && /usr/bin/python3 -c "import stl" 2>/dev/null; then
    for k in 0 1; do
        openscad -q -D 'show="printed"' -D fn=16 -o "$tmp/p$k.stl" "$tmp/s$k/shell-rod-nylon-printed.scad" 2>/dev/null
        /usr/bin/python3 tests/export_check.py stl "$tmp/p$k.stl" >"$tmp/p$k.json" 2>/dev/null
    done
    # OpenSCAD's 16-facet sphere and cylinders are too coarse for the closed
    # form: the check is that it renders and the sockets take material away
    python3 -c "import json,sys; a,b=(json.load(open(f))['volume_mm3'] for f in sys.argv[1:]); sys.exit(0 if b > 0 and a - b > 10 else 1)" \
        "$tmp/p0.json" "$tmp/p1.json" && ok || bad "OpenSCAD: the sockets do not render or remove nothing"
fi

expect_fail "--sockets needs --split" 2 "--sockets needs --split" -- export $d -o "$tmp/x" --sockets
finish
