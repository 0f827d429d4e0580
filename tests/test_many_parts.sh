#!/usr/bin/env bash
# Designs with many printed bodies (issue 28, item 6): a valid design of 42
# parts (a shell and 41 separate discs) is exported and built (it failed with
# "more than 32 output files at once", exit 1, after the work), and a design of
# 50 parts (the most a design may have: a shell and 49 concentric tubes) split
# in halves writes 100 STL files and more than 64 files in all (export's old
# fixed list of paths): every file the report names is written, once, and the
# 3MF holds every body. Usage: test_many_parts.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
cp designs/materials.json "$tmp/"

python3 - "$tmp/discs.json" "$tmp/tubes.json" <<'EOF'
import json, sys
shell = {"name": "shell", "shape": "shell", "thickness_mm": 3, "material": "ABSplus"}
discs = [dict(name="disc%02d" % i, shape="cylinder", radius_mm=3, height_mm=0.4, z_mm=-20 + i,
              material="ABSplus") for i in range(41)]
discs[20]["moving"] = True
json.dump({"name": "42 parts", "radius_mm": 25, "travel_mm": [-0.5, 0.5],
           "parts": [shell] + discs}, open(sys.argv[1], "w"), indent=1)
tubes = [dict(name="tube%02d" % i, shape="tube", inner_radius_mm=1 + 0.44 * i,
              radius_mm=1.24 + 0.44 * i, height_mm=6, material="ABSplus") for i in range(49)]
tubes[0]["moving"] = True
json.dump({"name": "50 parts", "radius_mm": 25, "travel_mm": [-0.5, 0.5],
           "parts": [dict(shell, thickness_mm=1.5)] + tubes}, open(sys.argv[2], "w"), indent=1)
EOF

# written OUTDIR JSON MIN: the run's --json lists at least MIN files, each once,
# each written into OUTDIR, and nothing else is there; the 3MF has one object per STL.
written() {
    python3 - "$@" <<'EOF'
import json, os, sys, zipfile, xml.etree.ElementTree as ET
out, report, least = sys.argv[1], json.load(open(sys.argv[2])), int(sys.argv[3])
files = report["files"]
assert len(files) >= least, (len(files), least)
assert len(set(files)) == len(files), "a file named twice"
for f in files:
    assert os.path.getsize(f) > 0, f
assert sorted(os.path.basename(f) for f in files) == sorted(os.listdir(out)), "other files"
stl = [f for f in files if f.endswith(".stl") and "-gauge-" not in f]
z = zipfile.ZipFile([f for f in files if f.endswith(".3mf")][0])
model = ET.fromstring(z.read("3D/3dmodel.model"))
objects = model.findall(".//{http://schemas.microsoft.com/3dmanufacturing/core/2015/02}object")
assert len(objects) == len(stl), (len(objects), len(stl))
EOF
}

"$tippe" export "$tmp/discs.json" -o "$tmp/e42" --json >"$tmp/e42.json" 2>"$tmp/err"
st=$?
check "export of a 42-part design exits 0, not $st ($(grep -v warning "$tmp/err"))" test $st -eq 0 &&
    check "export of 42 parts: 41 STL files (discs 19 and 20 touch: one body), the 3MF, SCAD and drawings, each written once" \
        written "$tmp/e42" "$tmp/e42.json" 45
"$tippe" build "$tmp/discs.json" -o "$tmp/b42" --json >"$tmp/b42.json" 2>"$tmp/err"
st=$?
check "build of a 42-part design exits 0, not $st ($(grep -v warning "$tmp/err"))" test $st -eq 0 &&
    check "build of 42 parts: the sheet's files and export's, each written once" \
        written "$tmp/b42" "$tmp/b42.json" 51
"$tippe" export "$tmp/tubes.json" -o "$tmp/e50" --split --json >"$tmp/e50.json" 2>"$tmp/err"
st=$?
check "export --split of a 50-part design exits 0, not $st ($(grep -v warning "$tmp/err"))" test $st -eq 0 &&
    check "export --split of 50 parts: over 64 files, each written once" \
        written "$tmp/e50" "$tmp/e50.json" 65

# Stopped while its hundred files are written: nothing left (the table of
# temporaries grew past its first block of 32 while the handler may walk it).
for ms in 300 600 900; do
    "$tippe" export "$tmp/tubes.json" -o "$tmp/s$ms" --split >/dev/null 2>"$tmp/err" &
    pid=$!
    sleep "0.$ms"
    kill -INT "$pid"
    wait "$pid"
    st=$?
    [ "$st" -eq 0 ] && continue # finished first
    check "export --split of 50 parts, SIGINT after $ms ms: exit 130 (got $st)" test "$st" -eq 130
    check "export --split of 50 parts, SIGINT after $ms ms: no temporary and no directory left" \
        test ! -e "$tmp/s$ms"
done
finish
