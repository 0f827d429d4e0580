#!/usr/bin/env bash
# An interrupted tippe build or tippe export into a new directory (issue 28,
# item 5): SIGINT or SIGTERM at a random moment (20 runs) stops it with exit
# 130 or 143, no temporary left, and the directory the run made removed, as a
# failed run removes it; a directory that was there before stays. A run the
# signal came too late for ends normally (exit 0, its files there).
# Usage: test_signals_dir.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
design=designs/m12-setscrew.json
RANDOM=28 # the same delays every run of the test

stopped=0
# one VERB SIG DELAY_MS ARGS...: VERB the design into a new directory, SIG after DELAY_MS.
one() {
    local verb=$1 sig=$2 ms=$3 i=$4
    shift 4
    local run=$tmp/r$i
    mkdir "$run"
    "$tippe" "$verb" "$design" -o "$run/out" "$@" >/dev/null 2>"$run/err" &
    local pid=$!
    sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
    kill -"$sig" "$pid" 2>/dev/null
    wait "$pid"
    local st=$? want=130
    [ "$sig" = TERM ] && want=143
    local left
    left=$(find "$run" -name '*.tmp.*')
    check "$verb, SIG$sig after $ms ms: no temporary left ($left)" test -z "$left"
    if [ "$st" -eq 0 ]; then # finished before the signal
        check "$verb, SIG$sig after $ms ms (too late): its files are there" test -s "$run/out/m12-setscrew.3mf"
        return
    fi
    stopped=$((stopped + 1))
    check "$verb, SIG$sig after $ms ms: exit $want (got $st: $(cat "$run/err"))" test "$st" -eq "$want"
    check "$verb, SIG$sig after $ms ms: the directory it made is removed ($(ls -A "$run/out" 2>/dev/null | tr '\n' ' '))" \
        test ! -e "$run/out"
}

# tippe build of the M12 ball takes about 0.3 s, its export at --chord-mm 0.001 about 0.4 s
# (more on a loaded machine): signals within the first 0.4 s mostly land in the work.
for i in $(seq 1 10); do
    [ $((i % 2)) -eq 0 ] && sig=TERM || sig=INT
    one build "$sig" $((10 + RANDOM % 390)) "b$i"
    one export "$sig" $((10 + RANDOM % 390)) "e$i" --chord-mm 0.001
done
echo "$test_name: $stopped of 20 runs stopped by the signal"
check "most runs were stopped by the signal ($stopped of 20)" test "$stopped" -ge 10

# A directory that was there before is kept (and left as it was: empty).
mkdir "$tmp/keep"
"$tippe" export "$design" -o "$tmp/keep" --chord-mm 0.001 >/dev/null 2>"$tmp/err" &
pid=$!
sleep 0.05
kill -INT "$pid"
wait "$pid"
st=$?
if [ "$st" -ne 0 ]; then
    check "an existing directory stays after SIGINT" test -d "$tmp/keep"
    check "an existing directory is left empty after SIGINT" test -z "$(ls -A "$tmp/keep")"
fi
finish
