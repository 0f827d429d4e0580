#!/usr/bin/env bash
# tippe-mpi: launches and maps shared among MPI ranks give exactly the single-process
# result (byte-identical JSON), through tippe-mpi and through the plain tippe under
# mpirun (which replaces itself by tippe-mpi). Skipped, saying so, when tippe-mpi was
# not built or mpirun is missing. Usage: test_mpi.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
mpi=$(dirname "$tippe")/tippe-mpi
[ -x "$mpi" ] || skip "$mpi was not built (Open MPI not found at configure time)"
command -v mpirun >/dev/null 2>&1 || skip "mpirun not found"
# Open MPI refuses to start as root unless told (CI runs as root).
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
m12=designs/m12-setscrew.json
quick=(--accuracy fast --t-end 40)
# One OpenMP thread per rank: two ranks on a shared machine are enough load.
run_mpi() { mpirun -np "$1" --oversubscribe -x OMP_NUM_THREADS=1 "${@:2}"; }

OMP_NUM_THREADS=1 "$tippe" launch "$m12" --z2 15 -n 12 --seed 9 "${quick[@]}" --json \
    >"$tmp/single.json"
check "single-process launch exits 0" test $? -eq 0

run_mpi 2 "$mpi" launch "$m12" --z2 15 -n 12 --seed 9 "${quick[@]}" --json >"$tmp/mpi2.json"
check "tippe-mpi launch on 2 ranks exits 0" test $? -eq 0
check "launch: 2 ranks give the single-process JSON byte for byte" \
    cmp -s "$tmp/single.json" "$tmp/mpi2.json"

run_mpi 2 "$tippe" launch "$m12" --z2 15 -n 12 --seed 9 "${quick[@]}" --json >"$tmp/plain2.json"
check "plain tippe under mpirun -np 2 exits 0" test $? -eq 0
check "launch: tippe under mpirun (re-executed as tippe-mpi) gives the same JSON" \
    cmp -s "$tmp/single.json" "$tmp/plain2.json"

run_mpi 1 "$mpi" launch "$m12" --z2 15 -n 12 --seed 9 "${quick[@]}" --json >"$tmp/mpi1.json"
check "launch: tippe-mpi on 1 rank gives the same JSON" cmp -s "$tmp/single.json" "$tmp/mpi1.json"

OMP_NUM_THREADS=1 "$tippe" map "$m12" --z2 10:20:3 --spin 5:25rev/s:2 -n 2 "${quick[@]}" --json \
    >"$tmp/map1.json"
run_mpi 2 "$mpi" map "$m12" --z2 10:20:3 --spin 5:25rev/s:2 -n 2 "${quick[@]}" --json \
    --csv "$tmp/map.csv" >"$tmp/map2.json"
check "map: 2 ranks give the single-process JSON byte for byte" \
    cmp -s "$tmp/map1.json" "$tmp/map2.json"
check "map under MPI: rank 0 alone wrote the CSV (a header and 6 cells)" \
    test "$(wc -l <"$tmp/map.csv")" -eq 7

# Errors: rank 0 reports once, every rank exits 2, nothing hangs.
run_mpi 2 "$mpi" launch "$m12" --z2 30 -n 2 >"$tmp/bad.out" 2>"$tmp/bad.err"
check "bad Z2 under MPI exits non-zero" test $? -ne 0
check "bad Z2 under MPI: the message is printed once" \
    test "$(grep -c "outside the design's travel" "$tmp/bad.err")" -eq 1

# Verbs without a parallel form run once, on rank 0.
run_mpi 2 "$mpi" eval "$m12" --z2 5 >"$tmp/eval.out"
check "eval under tippe-mpi prints once" test "$(grep -c '^design' "$tmp/eval.out")" -eq 1

finish
