#!/usr/bin/env bash
# tippe serve's build zip of a design with an uploaded G-code (issue 37,
# tests/serve_zip_gcode.py): the G-code travels in the zip beside the design, which names it
# relative to itself, and `tippe build` on the unzipped design gives the page's verdict.
# Needs PrusaSlicer (tippe slice) to make the G-code.
# Usage: test_serve_zip_gcode.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v "${PRUSA_SLICER:-prusa-slicer}" >/dev/null ||
    { echo "SKIPPED: prusa-slicer is not installed (TIPPE_WITH_SLICER=1 tools/deps.sh)"; exit 0; }
exec python3 "$(dirname "$0")/serve_zip_gcode.py" "$tippe" "$(dirname "$tippe")/serve-zip-gcode"
