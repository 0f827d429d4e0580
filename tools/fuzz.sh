#!/usr/bin/env bash
# Builds tippe's libFuzzer targets (tests/fuzz/) with clang, ASan and UBSan, and
# runs each on its seeds, the files tippe ships (docs/fuzzing.md).
#
#   tools/fuzz.sh                       every target for 60 s
#   tools/fuzz.sh --time 3600 design    one target for an hour
#   tools/fuzz.sh --time 3 --runs 20000 --corpus DIR   (the test suite's short run)
#
# Options: --build-dir DIR (default build-fuzz), --time SECONDS per target,
# --runs N (at most N inputs per target), --corpus DIR (where the inputs found
# are kept, one folder per target; default BUILD_DIR/corpus, kept between runs),
# --jobs J (build jobs, default 1). A crash, a leak, an ASan or UBSan report or
# a timeout stops the target; the input is saved as BUILD_DIR/artifacts/TARGET-*
# and the exit status is 1. Exit 77 when clang or its libFuzzer is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=build-fuzz time=60 runs="" corpus="" jobs=1 targets=()
while [ $# -gt 0 ]; do
    case $1 in
    --build-dir) build=$2; shift 2 ;;
    --time) time=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --corpus) corpus=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    -*) echo "tools/fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
    esac
done
all=(design materials catalogue spec scenario options gcode)
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")
corpus=${corpus:-$build/corpus}

if ! command -v clang >/dev/null; then
    echo "tools/fuzz.sh: clang not found: the fuzz targets need clang's libFuzzer" \
         "(Debian: apt-get install clang libclang-rt-dev)" >&2
    exit 77
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n) { return 0; }' >"$probe/p.c"
if ! clang -fsanitize=fuzzer "$probe/p.c" -o "$probe/p" 2>"$probe/err"; then
    echo "tools/fuzz.sh: clang cannot link libFuzzer (Debian: apt-get install" \
         "libclang-rt-dev): $(head -1 "$probe/err")" >&2
    exit 77
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
    CC=clang cmake -S . -B "$build" -DTIPPE_FUZZ=ON -DTIPPE_MPI=OFF \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$probe/configure.log" 2>&1 ||
        { cat "$probe/configure.log" >&2; exit 1; }
fi
nice -n 10 cmake --build "$build" --target tippe_fuzz -j"$jobs" >"$probe/build.log" 2>&1 ||
    { tail -40 "$probe/build.log" >&2; exit 1; }

# seeds: the shipped files each loader reads (options: the command lines of
# README.md and docs/ for the launch verbs, one argument per line)
seeds=$build/seeds
rm -rf "$seeds"
mkdir -p "$seeds"/{design,materials,catalogue,spec,scenario,options,gcode}
for f in designs/*.json; do
    case $f in
    designs/materials.json) cp "$f" "$seeds/materials/" ;;
    designs/catalogue.json) cp "$f" "$seeds/catalogue/" ;;
    *) cp "$f" "$seeds/design/" ;;
    esac
done
cp designs/optimise/*.json "$seeds/spec/"
cp designs/scenarios/*.json "$seeds/scenario/"
cp tests/data/gcode/*.gcode "$seeds/gcode/"
k=0
grep -h -E '^ *(build/)?tippe (simulate|animate) ' README.md docs/*.md | sed -E 's/^ *(build\/)?tippe [a-z]+ //' |
    while read -r line; do
        k=$((k + 1))
        # shellcheck disable=SC2086 # one argument per word, as the shell splits them
        printf '%s\n' $line >"$seeds/options/cmd$k.txt"
    done

mkdir -p "$build/artifacts"
status=0
for t in "${targets[@]}"; do
    exe=$build/tests/fuzz/fuzz_$t
    [ -x "$exe" ] || { echo "tools/fuzz.sh: no target '$t' (targets: ${all[*]})" >&2; exit 2; }
    mkdir -p "$corpus/$t"
    dict=()
    [ "$t" = options ] || [ "$t" = gcode ] || dict=(-dict="$root/tests/fuzz/json.dict")
    limit=()
    [ -z "$runs" ] || limit=(-runs="$runs")
    log=$build/fuzz_$t.log
    # -seed fixes the mutations; each input gets 10 s and 2 GiB at most
    if "$exe" -seed=1 -max_total_time="$time" "${limit[@]}" "${dict[@]}" -timeout=10 \
        -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$t-" -print_final_stats=1 \
        "$corpus/$t" "$seeds/$t" >"$log" 2>&1; then
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        secs=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
        cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1)
        echo "fuzz_$t: ${execs:-?} inputs, ${secs:-?} exec/s, $cov, no failure"
    else
        status=1
        echo "fuzz_$t: FAILED (log $log):"
        grep -E 'ERROR|SUMMARY|Test unit written|==[0-9]+==' "$log" | head -20
    fi
done
exit $status
