#!/usr/bin/env bash
# SIGINT and SIGTERM stop the tippe command cleanly (issue 10, defect 4): the work
# stops at once, every temporary output file is removed, old files are left as
# they were, one line says so, and the exit status is 130 (SIGINT) or 143 (SIGTERM).
# Usage: test_io_signals.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
m3=designs/m3-setscrew.json
sc=designs/scenarios/fig12-tip.json
d=$tmp/d
mkdir -p "$d"

nothing_left() { [ -z "$(find "$1" -name '*.tmp.*' -print -quit)" ]; }
same_text() { [ "$(cat "$1")" = "$2" ]; }
# wait_for GLOB: waits (at most 60 s) until a file matching GLOB exists.
wait_for() {
    local i
    for ((i = 0; i < 1200; i++)); do
        compgen -G "$1" >/dev/null && return 0
        sleep 0.05
    done
    return 1
}
# stopped NAME SIGNAL STATUS PID: PID ended with STATUS after one line naming SIGNAL.
stopped() {
    local name=$1 sig=$2 want=$3 pid=$4 st
    wait "$pid"
    st=$?
    check "$name: exit $want (got $st)" test "$st" -eq "$want"
    # one line besides the M3's warning of its light screw (a negligible moving weight)
    check "$name: one line on stderr naming $sig" \
        test "$(grep -c "stopped by $sig" "$d/err")" -eq 1 -a "$(grep -vc ': warning: .*the moving weight is' "$d/err")" -eq 1
}

# --- during the work: map and launch (minutes of launches), killed after 1 s -----
# Viscous friction (the default, given explicitly): under the Coulomb law the M3 ball's slow
# launches stick and are decided rolling within a second, which would leave nothing to interrupt.
for sig in INT TERM; do
    [ "$sig" = INT ] && want=130 || want=143
    echo "old csv" >"$d/map.csv"
    echo "old png" >"$d/map.png"
    "$tippe" map "$m3" --z2 3:5:4 --spin 5:20:4 -n 50 --friction viscous --csv "$d/map.csv" \
        --plot "$d/map.png" >/dev/null 2>"$d/err" &
    pid=$!
    sleep 1
    t0=$(date +%s%N)
    kill -"$sig" "$pid"
    stopped "map, SIG$sig during the launches" "SIG$sig" "$want" "$pid"
    ms=$((($(date +%s%N) - t0) / 1000000))
    # the whole map takes minutes; a stop within 5 s (loaded machine) is "at once"
    check "map, SIG$sig: stopped at once (${ms} ms)" test "$ms" -lt 5000
    check "map, SIG$sig: the old CSV is untouched" same_text "$d/map.csv" "old csv"
    check "map, SIG$sig: the old plot is untouched" same_text "$d/map.png" "old png"
    check "map, SIG$sig: no temporary left" nothing_left "$d"

    echo "old csv" >"$d/launch.csv"
    "$tippe" launch "$m3" --z2 4 -n 2000 --friction viscous --csv "$d/launch.csv" >/dev/null \
        2>"$d/err" &
    pid=$!
    sleep 1
    kill -"$sig" "$pid"
    stopped "launch, SIG$sig during the launches" "SIG$sig" "$want" "$pid"
    check "launch, SIG$sig: the old CSV is untouched" same_text "$d/launch.csv" "old csv"
    check "launch, SIG$sig: no temporary left" nothing_left "$d"
done

# --- while the outputs are being written ----------------------------------------
# The plot goes to a FIFO nobody reads, so the command blocks there with the CSV
# already finished under its temporary name: the signal must remove it.
mkfifo "$d/blocked.png"
for sig in INT TERM; do
    [ "$sig" = INT ] && want=130 || want=143
    echo "old csv" >"$d/sim.csv"
    "$tippe" simulate "$sc" --csv "$d/sim.csv" --plot "$d/blocked.png" >/dev/null 2>"$d/err" &
    pid=$!
    check "simulate: the CSV's temporary appears" wait_for "$d/sim.csv.tmp.*"
    sleep 0.2 # into the blocking open of the FIFO
    kill -"$sig" "$pid"
    stopped "simulate, SIG$sig while writing" "SIG$sig" "$want" "$pid"
    check "simulate, SIG$sig: the finished CSV temporary is removed" nothing_left "$d"
    check "simulate, SIG$sig: the old CSV is untouched" same_text "$d/sim.csv" "old csv"
    check "simulate, SIG$sig: the FIFO is still a FIFO" test -p "$d/blocked.png"

    echo "old csv" >"$d/map.csv"
    "$tippe" map "$m3" --z2 4:4:1 --spin 10:10:1 -n 2 --csv "$d/map.csv" \
        --plot "$d/blocked.png" >/dev/null 2>"$d/err" &
    pid=$!
    check "map: the CSV's temporary appears" wait_for "$d/map.csv.tmp.*"
    sleep 0.2
    kill -"$sig" "$pid"
    stopped "map, SIG$sig while writing" "SIG$sig" "$want" "$pid"
    check "map, SIG$sig: the finished CSV temporary is removed" nothing_left "$d"
    check "map, SIG$sig: the old CSV is untouched" same_text "$d/map.csv" "old csv"
done

finish
