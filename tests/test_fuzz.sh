#!/usr/bin/env bash
# The libFuzzer targets (tests/fuzz/, docs/fuzzing.md) run briefly: each file a
# user feeds tippe (design, materials table, catalogue, optimisation spec,
# scenario, a slicer's G-code) and the option parser gets 3 s (at most 20000 inputs) from its seeds,
# the shipped files, with a fixed seed, under ASan and UBSan; a crash, a leak or
# a sanitizer report fails the test. tools/fuzz.sh builds the targets with clang
# beside the tested build (BUILD/tests/fuzz-build; a -DTIPPE_FUZZ=ON build is
# used as it is). Skipped, saying so, where clang or its libFuzzer is missing.
# Usage: test_fuzz.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
build=$(cd "$(dirname "$tippe")" && pwd)
grep -q '^TIPPE_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null || build=$build/tests/fuzz-build
"$(dirname "$0")/../tools/fuzz.sh" --build-dir "$build" --time 3 --runs 20000 \
    --corpus "$tmp/corpus" >"$tmp/out" 2>&1
st=$?
[ $st -ne 77 ] || skip "$(head -1 "$tmp/out")"
cat "$tmp/out"
check "tools/fuzz.sh: every target ran without a failure (exit $st)" test $st -eq 0
for t in design materials catalogue spec scenario options gcode; do
    check "fuzz_$t ran its inputs" grep -qE "^fuzz_$t: [0-9]+ inputs, .* no failure" "$tmp/out"
done
finish
