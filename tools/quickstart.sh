#!/usr/bin/env bash
# Quick start: install what is missing, build, and run the main job (the zone table of the
# paper's M12 setscrew prototype). Usage: tools/quickstart.sh [DESIGN.json]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
design=${1:-designs/m12-setscrew.json}
mkdir -p out
./build/tippe sweep "$design" --plot out/zones.png
echo "zone plot: out/zones.png"
