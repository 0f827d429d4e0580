#!/usr/bin/env bash
# The house's rules (docs/architecture.md), checked on the objects of the tested
# build: every exported symbol has the tippe_ prefix and its module's name, no
# folder includes a header above its layer or another module's internal header,
# and no two files call each other around (a cycle) or up a layer.
# Usage: test_house.sh TIPPE (the build's tippe; its folder holds the objects).
set -euo pipefail
build=$(cd "$(dirname "$1")" && pwd)
command -v nm >/dev/null || { echo "SKIPPED: nm (binutils) is not installed"; exit 0; }
python3 "$(dirname "$0")/check_house.py" "$(cd "$(dirname "$0")/.." && pwd)" "$build"
