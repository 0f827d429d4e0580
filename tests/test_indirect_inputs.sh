#!/usr/bin/env bash
# Issue 19.1: an output must never replace a file the run reads indirectly (a
# design's materials table, a spec's catalogue and base design, a scenario's
# design): refused with exit 2 before any work, the file left byte for byte.
source "$(dirname "$0")/lib.sh"
setup "$@"

# A private copy of designs/, so that a regression cannot damage the repository.
d=$tmp/designs
mkdir -p "$d/optimise" "$d/scenarios"
cp designs/materials.json designs/catalogue.json designs/m12-setscrew.json \
   designs/m3-setscrew.json designs/drilled-ball-blind.json "$d/"
cp designs/optimise/drilled-ball.json designs/optimise/drilled-ball-catalogue.json "$d/optimise/"
cat >"$d/scenarios/on-design.json" <<'JSON'
{"top": {"design": "../m12-setscrew.json", "z2_mm": 12},
 "initial": {"theta": 0.1, "spin": 120}, "mu": 0.3, "t_end": 2}
JSON
ln -s materials.json "$d/materials-link.csv"
ln -s materials.json "$d/materials-link.png"
snapshot() { (cd "$d" && find . -type f -print0 | sort -z | xargs -0 md5sum); }
before=$(snapshot)

mat=$d/materials.json
t0=$(date +%s%N)
expect_fail "optimise -o the materials table" 2 "-o $mat is the materials file" -- \
    optimise "$d/optimise/drilled-ball.json" -o "$mat"
expect_fail "optimise -o the spec's base design" 2 "is the design file" -- \
    optimise "$d/optimise/drilled-ball.json" -o "$d/drilled-ball-blind.json"
expect_fail "optimise --csv the catalogue" 2 "is the catalogue file" -- \
    optimise "$d/optimise/drilled-ball-catalogue.json" -o "$tmp/best.json" --csv "$d/catalogue.json"
expect_fail "simulate --csv the materials table" 2 "is the materials file" -- \
    simulate "$d/m12-setscrew.json" --z2 12 --spin 20rev/s --csv "$mat"
expect_fail "simulate a scenario --csv its design" 2 "is the design file" -- \
    simulate "$d/scenarios/on-design.json" --csv "$d/m12-setscrew.json"
expect_fail "simulate a scenario --csv its design's materials" 2 "is the materials file" -- \
    simulate "$d/scenarios/on-design.json" --csv "$mat"
expect_fail "launch --csv the materials table" 2 "is the materials file" -- \
    launch "$d/m12-setscrew.json" --z2 12 -n 1000 --csv "$mat"
expect_fail "compare --csv the materials table" 2 "is the materials file" -- \
    compare "$d/m12-setscrew.json" "$d/m3-setscrew.json" --csv "$mat"
expect_fail "map --csv the materials table" 2 "is the materials file" -- \
    map "$d/m12-setscrew.json" --z2 0:20:21 --spin 2:30rev/s:29 -n 40 --csv "$mat"
expect_fail "sweep: a plot named through a link to the materials table" 2 "is the materials file" -- \
    sweep "$d/m12-setscrew.json" --plot "$d/materials-link.png"
expect_fail "through a symlink" 2 "is the materials file" -- \
    launch "$d/m12-setscrew.json" --z2 12 -n 1000 --csv "$d/materials-link.csv"
elapsed_ms=$((($(date +%s%N) - t0) / 1000000))
# 11 refusals; the refused map and launches alone would take minutes.
check "refused before any work (${elapsed_ms} ms for 11)" test "$elapsed_ms" -lt 15000
check "every file read is intact" test "$(snapshot)" = "$before"

# What is not read may still be written: the design's CSV beside it is fine.
check "an output beside the inputs is written" \
    exits 0 simulate "$d/m12-setscrew.json" --z2 12 --spin 20rev/s --t-end 0.1 --csv "$d/run.csv"
check "and it is a CSV" grep -q "theta" "$d/run.csv"
finish
