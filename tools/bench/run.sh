#!/usr/bin/env bash
# The speed-against-accuracy benchmark, in one command (not part of the tests):
#
#   tools/bench/run.sh [OUTDIR] [--quick] [--docs]
#
# Builds tippe and the tools in tools/bench/ (Release) into build-bench/,
# and writes into OUTDIR (default out/bench):
#   machine.txt        lscpu model and cores, compiler, GSL and SciPy versions
#   wp.csv             every GSL stepper x rtol 1e-3..1e-13 x scenario (work_precision.c)
#   reference.csv      the reference solutions and their mutual check
#   scipy.csv          the same scenarios and tolerances with SciPy (reference_scipy.py)
#   wp-SCENARIO.png    work-precision plot per scenario (wp_plot.c, PLplot)
#   levels.txt         cost of each level of detail (levels.c)
#   perf.txt           share of the run time in the right-hand side (perf, if present)
#   summary.md         tables: presets, best front, SciPy ratio at equal error
# --quick: three steppers, every other tolerance, SciPy DOP853 only (a smoke test).
# --docs: also copy the plots to docs/img/ (what docs/performance.md shows).
# About 8 minutes on the 2-core machine of docs/performance.md; timings are one core.
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT=out/bench
QUICK=""
DOCS=0
for a in "$@"; do
    case "$a" in
    --quick) QUICK=quick ;;
    --docs) DOCS=1 ;;
    -h | --help)
        sed -n '2,20p' "$0"
        exit 0
        ;;
    -*)
        echo "run.sh: unknown option $a" >&2
        exit 2
        ;;
    *) OUT="$a" ;;
    esac
done
PY=/usr/bin/python3 # Debian's, with numpy and scipy
mkdir -p "$OUT"
BUILD=build-bench
# Warnings as errors, as in CI; the bench programs are CMake targets (tools/CMakeLists.txt).
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DTIPPE_WERROR=ON >/dev/null
cmake --build "$BUILD" -j2 --target tippe-cli wp_work_precision wp_wp_plot wp_levels >/dev/null
BIN="$BUILD/tools/bench"

{
    lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket)'
    cc --version | head -1
    echo "GSL $(pkg-config --modversion gsl)"
    $PY -c 'import scipy, numpy; print("SciPy", scipy.__version__, "NumPy", numpy.__version__)'
    echo "date $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$OUT/machine.txt"
cat "$OUT/machine.txt"

echo "== work-precision (tippe)"
"$BIN/work_precision" "$OUT" $QUICK
echo "== SciPy"
$PY tools/bench/reference_scipy.py "$OUT" $QUICK
echo "== plots"
for s in $(tail -n +2 "$OUT/reference.csv" | cut -d, -f1); do
    "$BIN/wp_plot" "$OUT/wp-$s.png" "$s" "$OUT/wp.csv" "$OUT/scipy.csv"
    if [ "$DOCS" = 1 ]; then
        mkdir -p docs/img
        cp "$OUT/wp-$s.png" "docs/img/wp-$s.png"
    fi
done
echo "== levels of detail"
"$BIN/levels" designs/scenarios/fig12-tip.json 15 | tee "$OUT/levels.txt"
if command -v perf >/dev/null && perf record -o "$OUT/perf.data" -q -- \
    "$BIN/levels" designs/scenarios/fig12-tip.json 200 1 "$OUT/levels-tmp.csv" verdict \
    >/dev/null 2>&1; then
    # Self time per symbol; contact_eval is called by rhs (and once per step
    # for the monitors), so rhs + contact_eval is the right-hand side's share.
    perf report -i "$OUT/perf.data" --no-children --stdio 2>/dev/null | grep '%' \
        >"$OUT/perf-all.txt" || true
    head -12 "$OUT/perf-all.txt" >"$OUT/perf.txt"
    rm -f "$OUT/perf-all.txt" "$OUT/levels-tmp.csv"
    rm -f "$OUT/perf.data" "$OUT/perf.data.old"
    cat "$OUT/perf.txt"
else
    echo "perf not available: no RHS share measured" | tee "$OUT/perf.txt"
fi
$PY tools/bench/summarize.py "$OUT" >"$OUT/summary.md"
echo "== wrote $OUT/summary.md"
