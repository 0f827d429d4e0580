#!/usr/bin/env bash
# The speed-against-accuracy benchmark, in one command (not part of the tests):
#
#   tools/bench/run.sh [OUTDIR] [--quick] [--docs]
#
# Builds libtippe (Release) into build-bench/, compiles the tools in tools/bench/,
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
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j2 --target tippe tippe-cli >/dev/null
mkdir -p "$BUILD/bench"
# The same flags as the project (CMakeLists.txt), warnings as errors.
CFLAGS="-std=gnu11 -O3 -DNDEBUG -g -Wall -Wextra -Wshadow -Wstrict-prototypes -Wno-unused-parameter
        -Werror -ffp-contract=off -fopenmp -Iinclude $(pkg-config --cflags gsl libcjson plplot)"
LIBS="$BUILD/libtippe.a $(pkg-config --libs gsl libcjson plplot) -lm"
for t in work_precision wp_plot levels; do
    # shellcheck disable=SC2086
    cc $CFLAGS "tools/bench/$t.c" $LIBS -o "$BUILD/bench/$t"
done

{
    lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket)'
    cc --version | head -1
    echo "GSL $(pkg-config --modversion gsl)"
    $PY -c 'import scipy, numpy; print("SciPy", scipy.__version__, "NumPy", numpy.__version__)'
    echo "date $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$OUT/machine.txt"
cat "$OUT/machine.txt"

echo "== work-precision (tippe)"
"$BUILD/bench/work_precision" "$OUT" $QUICK
echo "== SciPy"
$PY tools/bench/reference_scipy.py "$OUT" $QUICK
echo "== plots"
for s in $(tail -n +2 "$OUT/reference.csv" | cut -d, -f1); do
    "$BUILD/bench/wp_plot" "$OUT/wp-$s.png" "$s" "$OUT/wp.csv" "$OUT/scipy.csv"
    if [ "$DOCS" = 1 ]; then
        mkdir -p docs/img
        cp "$OUT/wp-$s.png" "docs/img/wp-$s.png"
    fi
done
echo "== levels of detail"
"$BUILD/bench/levels" designs/scenarios/fig12-tip.json 15 | tee "$OUT/levels.txt"
if command -v perf >/dev/null && perf record -o "$OUT/perf.data" -q -- \
    "$BUILD/bench/levels" designs/scenarios/fig12-tip.json 200 1 "$OUT/levels-tmp.csv" verdict \
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
