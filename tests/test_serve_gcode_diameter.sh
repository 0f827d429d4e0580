#!/usr/bin/env bash
# tippe serve reads an uploaded G-code with the design's print.filament_diameter_mm, as the
# command reads a file (tests/serve_gcode_diameter.py). Needs PrusaSlicer to make the G-code.
# Usage: test_serve_gcode_diameter.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v "${PRUSA_SLICER:-prusa-slicer}" >/dev/null ||
    { echo "SKIPPED: prusa-slicer is not installed (TIPPE_WITH_SLICER=1 tools/deps.sh)"; exit 0; }
exec python3 "$(dirname "$0")/serve_gcode_diameter.py" "$tippe" "$(dirname "$tippe")/serve-gcode-diameter"
