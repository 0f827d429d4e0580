#!/usr/bin/env bash
# Reproducibility: the same scenario gives bit-identical results on repeated runs
# and at any thread count. Compares `--json` output (and launch CSV files) byte
# for byte: simulate twice, and with OMP_NUM_THREADS=1 against 2; launch with
# the same seed on 1 and 2 threads. The only field allowed to differ is
# simulate's elapsed_s (wall time). docs/performance.md lists the compiler
# flags that could change the last bits.
#   usage: bash tests/test_reproducible.sh /path/to/tippe   (from the repository root)
set -u
TIPPE=${1:?usage: test_reproducible.sh /path/to/tippe}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
pass=0
fail=0
check() { # check NAME FILE1 FILE2
    if cmp -s "$2" "$3"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL $1: $2 and $3 differ:"
        diff "$2" "$3" | head -10
    fi
}
run_ok() { # run_ok NAME CMD...: the command must succeed
    local name=$1
    shift
    if "$@"; then
        pass=$((pass + 1))
        return 0
    fi
    fail=$((fail + 1))
    echo "FAIL $name: exit status $?"
    return 1
}

# simulate: a hang and a flip (their final states depend on every step)
for sc in fig12-hang film-IIb-flip; do
    f=designs/scenarios/$sc.json
    for t in 1 2 2b; do
        n=${t%b}
        run_ok "simulate $sc threads $t" \
            env OMP_NUM_THREADS="$n" "$TIPPE" simulate "$f" --json >"$TMP/$sc.$t.raw" || continue
        grep -v '"elapsed_s"' "$TMP/$sc.$t.raw" >"$TMP/$sc.$t.json"
    done
    check "simulate $sc repeated" "$TMP/$sc.2.json" "$TMP/$sc.2b.json"
    check "simulate $sc 1 vs 2 threads" "$TMP/$sc.1.json" "$TMP/$sc.2.json"
    # it really ran: a verdict and a number of steps
    if grep -q '"verdict":' "$TMP/$sc.1.json" && grep -q '"steps":' "$TMP/$sc.1.json"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL simulate $sc: no verdict in the JSON"
    fi
done

# launch: many launches on OpenMP threads, same seed
if "$TIPPE" launch --help >/dev/null 2>&1; then
    for n in 1 2; do
        run_ok "launch threads $n" env OMP_NUM_THREADS=$n "$TIPPE" launch \
            designs/m12-setscrew.json --z2 5 -n 8 --seed 3 --json --csv "$TMP/launch.$n.csv" \
            >"$TMP/launch.$n.json"
    done
    check "launch JSON 1 vs 2 threads" "$TMP/launch.1.json" "$TMP/launch.2.json"
    check "launch CSV 1 vs 2 threads" "$TMP/launch.1.csv" "$TMP/launch.2.csv"
    if [ "$(wc -l <"$TMP/launch.1.csv")" -ge 9 ]; then # header + 8 launches
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL launch CSV has $(wc -l <"$TMP/launch.1.csv") lines, want >= 9"
    fi
else
    echo "note: no launch verb in $TIPPE; compared simulate only"
fi

echo "test_reproducible: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
