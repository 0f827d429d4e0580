#!/usr/bin/env bash
# Supports in tippe's 3MF (issue 37, docs/printing.md "Supports"): PrusaSlicer's automatic
# supports, from the build plate only, on the objects that want them (a surface facing down
# more than 45 degrees above the first layers: a ball printed whole, a shell's halves over
# their domes) and off on the others (a solid ball's halves stand on their cut faces, domes up).
# Usage: test_export_support.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
# design, export options (-: none), the support_material each object must have (in order)
while read -r design opts want; do
    [ "$opts" = - ] && opts=""
    out="$tmp/$(basename "$design" .json)$opts"
    # shellcheck disable=SC2086  # opts is one option or none
    "$tippe" export "$design" -o "$out" --format 3mf $opts >/dev/null 2>"$out.err" ||
        { bad "export $design $opts: $(cat "$out.err")"; continue; }
    "$py" - "$out"/*.3mf "$want" <<'PY' && ok || bad "$design $opts: supports are not $want"
import re, sys, zipfile
cfg = zipfile.ZipFile(sys.argv[1]).read("Metadata/Slic3r_PE_model.config").decode()
objs = cfg.split("<object ")[1:]
got = ",".join(re.search(r'key="support_material" value="(\d)"', o).group(1) for o in objs)
assert got == sys.argv[2], (got, sys.argv[2])
for o in objs:
    if 'key="support_material" value="1"' in o:
        assert 'key="support_material_buildplate_only" value="1"' in o, o
        assert 'key="support_material_auto" value="1"' in o, o
PY
done <<'LIST'
designs/m12-setscrew-printed.json - 1
designs/m12-setscrew-printed.json --split 0,0
designs/shell-rod-iron-printed.json --split 1,1
LIST
finish
