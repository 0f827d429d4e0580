#!/usr/bin/env bash
# Reproducibility: the same scenario gives bit-identical results on repeated runs
# and at any thread count. Compares `--json` output (and launch CSV files) byte
# for byte: simulate twice, and with OMP_NUM_THREADS=1 against 2; launch with
# the same seed on 1 and 2 threads. The only field allowed to differ is
# simulate's elapsed_s (wall time). docs/performance.md lists the compiler
# flags that could change the last bits.
#   usage: bash tests/test_reproducible.sh /path/to/tippe   (from the repository root)
source "$(dirname "$0")/lib.sh"
setup "$@"
same() { # same NAME FILE1 FILE2: the files are equal byte for byte (else show how not)
    if cmp -s "$2" "$3"; then
        ok
    else
        bad "$1: $2 and $3 differ:"
        diff "$2" "$3" | head -10
    fi
}

# simulate: a hang and a flip (their final states depend on every step)
for sc in fig12-hang film-IIb-flip; do
    f=designs/scenarios/$sc.json
    for t in 1 2 2b; do
        n=${t%b}
        check "simulate $sc threads $t" \
            env OMP_NUM_THREADS="$n" "$tippe" simulate "$f" --json >"$tmp/$sc.$t.raw" || continue
        grep -v '"elapsed_s"' "$tmp/$sc.$t.raw" >"$tmp/$sc.$t.json"
    done
    same "simulate $sc repeated" "$tmp/$sc.2.json" "$tmp/$sc.2b.json"
    same "simulate $sc 1 vs 2 threads" "$tmp/$sc.1.json" "$tmp/$sc.2.json"
    # it really ran: a verdict and a number of steps
    if grep -q '"verdict":' "$tmp/$sc.1.json" && grep -q '"steps":' "$tmp/$sc.1.json"; then
        ok
    else
        bad "simulate $sc: no verdict in the JSON"
    fi
done

# launch: many launches on OpenMP threads, same seed
for n in 1 2; do
    check "launch threads $n" env OMP_NUM_THREADS=$n "$tippe" launch \
        designs/m12-setscrew.json --z2 5 -n 8 --seed 3 --json --csv "$tmp/launch.$n.csv" \
        >"$tmp/launch.$n.json"
done
same "launch JSON 1 vs 2 threads" "$tmp/launch.1.json" "$tmp/launch.2.json"
same "launch CSV 1 vs 2 threads" "$tmp/launch.1.csv" "$tmp/launch.2.csv"
if [ "$(wc -l <"$tmp/launch.1.csv")" -ge 9 ]; then # header + 8 launches
    ok
else
    bad "launch CSV has $(wc -l <"$tmp/launch.1.csv") lines, want >= 9"
fi

finish
