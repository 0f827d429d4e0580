#!/usr/bin/env bash
# Another slicer's G-code read back (issue 40): the printed M12 sliced by Debian's CuraEngine 4.13
# at 1.75 mm filament and read with the design's print.filament_diameter_mm. CuraEngine's
# printer definitions come from Cura's package (tools/deps.sh takes them out of it into
# $TIPPE_CURA_RESOURCES). Skipped, with a line naming cura-engine, when either is absent.
# Usage: test_cura.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
res="${TIPPE_CURA_RESOURCES:-/usr/local/share/tippe/cura-resources}"
[ -f "$res/definitions/fdmprinter.def.json" ] || res=/usr/share/cura/resources
if ! command -v CuraEngine >/dev/null || [ ! -f "$res/definitions/fdmprinter.def.json" ]; then
    echo "$test_name: cura-engine (CuraEngine) or Cura's printer definitions not found: skipped" \
         "(TIPPE_WITH_CURA=1 tools/deps.sh installs the Debian package cura-engine and takes the" \
         "definitions out of the cura package)"
    finish
    exit $?
fi
d=designs/m12-setscrew-printed.json
# the body's STL as exported, the hole at the design's 11 mm (no clearance), its bottom at z 0
"$tippe" export $d -o "$tmp" --format stl --clearance-mm 0 --json >"$tmp/export.json" ||
    { bad "tippe export"; finish; exit $?; }
zb=$("$py" -c 'import json,sys; print(-json.load(open(sys.argv[1]))["bodies"][0]["bbox_min_mm"][2])' "$tmp/export.json")
# the design's print settings as CuraEngine takes them: its command line evaluates no setting's
# formula, so the derived widths and the infill's line distance are given (gyroid: the line
# width over the density, fdmprinter.def.json's infill_line_distance)
export CURA_ENGINE_SEARCH_PATH="$res/definitions:$res/extruders"
if CuraEngine slice -j "$res/definitions/fdmprinter.def.json" -s machine_width=200 \
        -s machine_depth=200 -s machine_height=200 -s machine_center_is_zero=true \
        -s layer_height=0.2 -s layer_height_0=0.2 -s line_width=0.45 -s wall_line_width=0.45 \
        -s wall_line_width_0=0.45 -s wall_line_width_x=0.45 -s skin_line_width=0.45 \
        -s infill_line_width=0.45 -s wall_line_count=2 -s top_layers=4 -s bottom_layers=4 \
        -s infill_sparse_density=15 -s infill_line_distance=3.0 -s infill_pattern=gyroid \
        -s fill_outline_gaps=true -e0 -s material_diameter=1.75 \
        -l "$tmp/m12-setscrew-printed-body.stl" -s mesh_position_z="$zb" -o "$tmp/m12.gcode" \
        >"$tmp/cura.log" 2>&1; then
    ok
else
    bad "CuraEngine failed: $(tail -3 "$tmp/cura.log")"
    finish
    exit $?
fi
grep -q "^;Generated with Cura_SteamEngine" "$tmp/m12.gcode" && ok || bad "not Cura's G-code"
"$tippe" eval $d --z2 5 --json --set "parts.body.print.gcode=$tmp/m12.gcode" \
    --set parts.body.print.filament_diameter_mm=1.75 >"$tmp/eval.json" 2>"$tmp/eval.err" &&
"$py" - "$tmp/eval.json" <<'PY' && ok || bad "Cura's G-code read at 1.75 mm: $(tail -3 "$tmp/eval.err")"
import json, sys
p = [q for q in json.load(open(sys.argv[1]))["printed_parts"] if q["model"] == "gcode"][0]
assert p["gcode_generator"].startswith("Cura_SteamEngine"), p
# mass within 8 % of the print model, which follows PrusaSlicer's rules: CuraEngine 4.13 lays
# its top and bottom skins top_layers thick measured vertically and does not thicken them under
# a slope (PrusaSlicer's ensure_vertical_shell_thickness, which the model follows, puts 1.65 mm
# of solid infill under the M12's 39 degree slope): measured 17.13 g against 18.12 g (+5.8 %).
# Read with Cura's default 2.85 mm the mass would be 0.38 x: the diameter is the design's
assert abs(p["model_mass_kg"] / p["printed_mass_kg"] - 1) < 0.08, p
PY
# the design's diameter is the one applied: read at 2.85 mm every bead holds (2.85 / 1.75)^2 as
# much plastic (each move's E is the same filament length), to rounding, before the hole's cut
# (wider beads reach further into the hole: the cut is not in proportion)
"$tippe" eval $d --z2 5 --json --set "parts.body.print.gcode=$tmp/m12.gcode" \
    --set parts.body.print.filament_diameter_mm=2.85 >"$tmp/eval285.json" 2>"$tmp/eval.err" &&
"$py" - "$tmp/eval.json" "$tmp/eval285.json" <<'PY' && ok || bad "the design's filament diameter applied: $(tail -3 "$tmp/eval.err")"
import json, sys
a, b = ([q for q in json.load(open(f))["printed_parts"] if q["model"] == "gcode"][0]
        for f in sys.argv[1:3])
ma, mb = (q["printed_mass_kg"] + q["gcode_cut_mass_kg"] for q in (a, b))
assert abs(mb / ma - (2.85 / 1.75) ** 2) < 1e-9, (ma, mb)
PY
finish
