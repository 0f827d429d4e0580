#!/usr/bin/env bash
# Quick start: install what is missing, build, and run the main job (the zone table of the
# paper's M12 setscrew prototype). Usage: tools/quickstart.sh [DESIGN.json]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/deps.sh
echo "tippe: building into build/ ..." >&2
mkdir -p build
if ! { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j"$(nproc)"; } \
     >build/build.log 2>&1; then
  tail -n 40 build/build.log >&2
  echo "tippe: the build failed; the whole log is build/build.log" >&2
  exit 1
fi
design=${1:-designs/m12-setscrew.json}
mkdir -p out
./build/tippe sweep "$design" --plot out/zones.png
echo "zone plot: out/zones.png"
echo
echo "The same as a web page, live as you change the design: run"
echo "    ./build/tippe serve"
echo "and open http://127.0.0.1:8765/ (docs/serve.md)."
