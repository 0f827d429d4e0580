#!/usr/bin/env bash
# I/O safety of the tippe command (issue 10, defects 1, 2, 3 and 5): where the bytes
# of an output go (devices, FIFOs, symlinks, "-"), failed writes (a file-size limit,
# /dev/full) reported with exit 1 and the old file kept, output sets committed all
# or none, and bad output paths refused before any work. Usage: test_io.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
sc=designs/scenarios/fig12-tip.json # 0.1 s to integrate
m3=designs/m3-setscrew.json
d=$tmp/d
mkdir -p "$d"
tippe_abs=$(realpath "$tippe")

# limited KIB ARGS...: tippe ARGS under a file-size limit of KIB KiB with SIGXFSZ
# ignored (so that a write past it fails with EFBIG); stderr in $d/err.
limited() {
    local kib=$1
    shift
    (
        ulimit -f "$kib"
        trap '' XFSZ
        "$tippe" "$@" >/dev/null 2>"$d/err"
    )
}
# nothing_left DIR: no temporary ("*.tmp.*") left in DIR.
nothing_left() { [ -z "$(find "$1" -name '*.tmp.*' -print -quit)" ]; }
# same_text FILE TEXT: FILE holds exactly TEXT (and a newline).
same_text() { [ "$(cat "$1")" = "$2" ]; }
# wait_or_kill PID SECONDS: waits for PID, killing it after SECONDS; its status in $waited.
wait_or_kill() {
    local pid=$1 i
    for ((i = 0; i < $2 * 10; i++)); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -0 "$pid" 2>/dev/null && kill -KILL "$pid"
    wait "$pid"
    waited=$?
}

# A reference CSV, written to a new regular file.
"$tippe" simulate "$sc" --csv "$d/ref.csv" >/dev/null
check "simulate --csv to a new file exits 0" test $? -eq 0
check "the reference CSV has a header and rows" test "$(wc -l <"$d/ref.csv")" -gt 100

# --- defect 1: special files are written through, never replaced ---------------
# A symlink to /dev/null (not /dev/null itself, which an old build would replace).
ln -s /dev/null "$d/null.csv"
"$tippe" simulate "$sc" --csv "$d/null.csv" >/dev/null
check "--csv through a link to /dev/null exits 0" test $? -eq 0
check "the link to /dev/null is still a link" test -L "$d/null.csv"
check "/dev/null is still a character device" test -c /dev/null

# A FIFO with a reader gets the whole CSV and stays a FIFO.
mkfifo "$d/pipe.csv"
timeout 20 cat "$d/pipe.csv" >"$d/from-pipe.csv" &
reader=$!
timeout 20 "$tippe" simulate "$sc" --csv "$d/pipe.csv" >/dev/null
check "--csv to a FIFO exits 0" test $? -eq 0
wait "$reader"
check "the FIFO is still a FIFO" test -p "$d/pipe.csv"
check "the FIFO's reader got the whole CSV" cmp -s "$d/from-pipe.csv" "$d/ref.csv"

# A symlink to a regular file in another directory (relative link): the target
# is replaced, the link kept, no temporary left in either directory.
mkdir -p "$d/data" "$d/links"
echo old >"$d/data/real.csv"
chmod 640 "$d/data/real.csv"
ln -s ../data/real.csv "$d/links/link.csv"
"$tippe" simulate "$sc" --csv "$d/links/link.csv" >/dev/null
check "--csv through a relative symlink exits 0" test $? -eq 0
check "the symlink is still a symlink" test -L "$d/links/link.csv"
check "its target got the CSV" cmp -s "$d/data/real.csv" "$d/ref.csv"
check "the target kept its permissions (640)" test "$(stat -c %a "$d/data/real.csv")" = 640
check "no temporary next to the link or the target" nothing_left "$d"

# A dangling symlink: the file it names is created, the link kept.
ln -s new-target.csv "$d/dangling.csv"
"$tippe" simulate "$sc" --csv "$d/dangling.csv" >/dev/null
check "--csv through a dangling symlink creates its target" cmp -s "$d/new-target.csv" "$d/ref.csv"
check "the dangling symlink is kept" test -L "$d/dangling.csv"
# issue 28.8: a dangling symlink into a directory that does not exist is said to be one
ln -s no-such-dir/x.csv "$d/nowhere.csv"
expect_fail "--csv through a symlink into no directory" 2 "a dangling symlink to" "no-such-dir/x.csv" \
    "whose directory does not exist" -- simulate "$sc" --csv "$d/nowhere.csv"
# ... and as -o of export, the directory it points to is made (was "File exists")
ln -s new-export "$d/export-link"
"$tippe" export designs/m12-setscrew.json -o "$d/export-link" >/dev/null 2>"$d/export-link.err"
st=$?
check "export -o a dangling symlink exits 0: $(head -1 "$d/export-link.err")" test $st -eq 0
check "export -o a dangling symlink: the link kept, its target made" \
    test -L "$d/export-link" -a -d "$d/new-export" -a -s "$d/new-export/m12-setscrew.3mf"
ln -s no-such-dir/out "$d/export-nowhere"
expect_fail "export -o a dangling symlink into no directory" 2 "-o $d/export-nowhere: a dangling symlink to" \
    "no-such-dir/out" -- export designs/m12-setscrew.json -o "$d/export-nowhere"
check "...and nothing made there" test ! -e "$d/no-such-dir"

# "-" is standard output.
# (run in $d, so that a build that takes "-" for a file name leaves it there)
(cd "$d" && "$tippe_abs" simulate "$OLDPWD/$sc" --csv - >"$d/stdout.txt")
check "--csv - exits 0" test $? -eq 0
check "--csv - writes the CSV to stdout" grep -qxF "$(head -1 "$d/ref.csv")" "$d/stdout.txt"
check "--csv - writes every row" test "$(grep -c '^[0-9]' "$d/stdout.txt")" -ge "$(($(wc -l <"$d/ref.csv") - 1))"
check "no file named '-' appears" test ! -e "$d/-"
# Issue 19.11: with an output on stdout, stdout is that file alone and the text
# report goes to stderr; a parser reading the pipe gets exactly the file.
"$tippe" simulate "$sc" --csv - 2>"$d/stdout.err" | cat >"$d/piped.csv"
check "--csv - | cat: the bytes --csv FILE writes, nothing else" cmp -s "$d/piped.csv" "$d/ref.csv"
check "--csv -: the text report is on stderr" grep -q "^verdict" "$d/stdout.err"
"$tippe" launch designs/m12-setscrew.json --z2 15 -n 3 --accuracy fast --t-end 20 --csv - \
    2>/dev/null | python3 -c '
import csv, sys
rows = list(csv.reader(sys.stdin))
assert len(rows) == 4 and all(len(r) == len(rows[0]) for r in rows), rows' 2>/dev/null
check "launch --csv - | a CSV parser: a header and 3 rows of equal width" test $? -eq 0
"$tippe" optimise tests/data/optimise-small.json -o - 2>/dev/null >"$d/best-piped.json"
check "optimise -o - | json.load: a design with parts" json_ok "$d/best-piped.json" "len(o['parts']) > 0"
"$tippe" eval "$d/best-piped.json" --z2 0 >/dev/null 2>&1
check "the piped best design loads in tippe eval" test $? -eq 0
"$tippe" simulate "$sc" --csv - >/dev/full 2>"$d/full.err"
check "--csv - into a full disk: exit 1" test $? -eq 1
check "--csv - into a full disk: says so" grep -q "No space left on device" "$d/full.err"
(cd "$d" && "$tippe_abs" export "$OLDPWD/designs/m12-setscrew.json" -o - >"$d/export.out" \
    2>"$d/export.err")
check "export -o -: refused with exit 2" test $? -eq 2
check "export -o -: the message says a directory is needed" grep -q "give a directory" "$d/export.err"
check "export -o -: no directory named '-'" test ! -e "$d/-"

# --- defect 2: a failed write is an error, and the old file survives -----------
"$tippe" sweep "$m3" >/dev/full 2>"$d/err"
check "sweep > /dev/full exits 1" test $? -eq 1
check "sweep > /dev/full says why" grep -q "writing to standard output failed: No space left on device" "$d/err"

# A file-size limit (ulimit -f, in KiB; SIGXFSZ ignored so that write fails with
# EFBIG): the CSV is 3 MB, so 100 KiB cuts it short.
echo "old csv" >"$d/keep.csv"
limited 100 simulate "$sc" --csv "$d/keep.csv"
check "a CSV cut short by ulimit -f exits 1" test $? -eq 1
check "the message names the CSV file and the reason" grep -q "keep.csv: writing the CSV file failed: File too large" "$d/err"
check "the old CSV is untouched" same_text "$d/keep.csv" "old csv"
check "no temporary is left" nothing_left "$d"
# The same without the trap: tippe catches SIGXFSZ itself.
(
    ulimit -f 100
    "$tippe" simulate "$sc" --csv "$d/keep.csv" >/dev/null 2>"$d/err"
)
check "without trap '' XFSZ: exit 1 too (not killed by SIGXFSZ)" test $? -eq 1
check "without trap '' XFSZ: the old CSV is untouched" same_text "$d/keep.csv" "old csv"

# A plot cut short (PLplot reports no write error of its own).
for ext in png svg pdf; do
    echo "old plot" >"$d/keep.$ext"
    limited 20 simulate "$sc" --plot "$d/keep.$ext"
    check "a $ext plot cut short by ulimit -f exits 1" test $? -eq 1
    check "the message names the $ext plot" grep -q "keep.$ext: writing the plot failed" "$d/err"
    check "the old $ext plot is untouched" same_text "$d/keep.$ext" "old plot"
done
check "no temporary is left after the plots" nothing_left "$d"

# --- defect 3: a set of outputs is committed all or none ------------------------
# The CSV (330 kB at --sample-dt 1) fits under 600 KiB, the SVG (1.1 MB) does not:
# the CSV is finished first, but its old file must survive the failed plot.
echo "old csv" >"$d/set.csv"
echo "old svg" >"$d/set.svg"
limited 600 simulate "$sc" --sample-dt 1 --csv "$d/set.csv" --plot "$d/set.svg"
check "simulate: a failed second output exits 1" test $? -eq 1
check "simulate: the first output's old file survives" same_text "$d/set.csv" "old csv"
check "simulate: the second output's old file survives" same_text "$d/set.svg" "old svg"
check "simulate: no temporary is left" nothing_left "$d"
# sweep: zone plot (PNG, ~100 kB) then phase plot (SVG, ~900 kB).
echo "old png" >"$d/zones.png"
echo "old svg" >"$d/phase.svg"
limited 300 sweep "$m3" --plot "$d/zones.png" --phase-plot "$d/phase.svg"
check "sweep: a failed phase plot exits 1" test $? -eq 1
check "sweep: the old zone plot survives" same_text "$d/zones.png" "old png"
check "sweep: the old phase plot survives" same_text "$d/phase.svg" "old svg"
# A new path that fails is not left behind either, and stdout failure keeps files.
echo "old csv" >"$d/stdout-set.csv"
"$tippe" simulate "$sc" --csv "$d/stdout-set.csv" >/dev/full 2>/dev/null
check "stdout failure: exit 1" test $? -eq 1
check "stdout failure: the CSV's old file survives" same_text "$d/stdout-set.csv" "old csv"
check "no temporary is left after the sets" nothing_left "$d"

# --- defect 5: bad output paths are refused before any work ---------------------
# A map of 10^6 launches would take hours: a refusal must come at once.
big=(map "$m3" --z2 3:5:100 --spin 5:20:100 -n 100)
mkdir -p "$d/adir" "$d/adir.png"
echo "a file" >"$d/afile"
before=$(ls -R "$d" | md5sum)
# Each refusal runs under a 30 s timeout, so that a build that starts the work
# fails here instead of computing for hours.
real_tippe=$tippe
tippe=$tmp/tippe-30s
printf '#!/bin/sh\nexec timeout 30 "%s" "$@"\n' "$real_tippe" >"$tippe"
chmod +x "$tippe"
t0=$(date +%s%N)
expect_fail "an existing directory" 2 "adir" "it is a directory" -- "${big[@]}" --csv "$d/adir"
expect_fail "a path through a regular file" 2 "afile/x.csv" "Not a directory" -- "${big[@]}" --csv "$d/afile/x.csv"
expect_fail "a path under /proc" 2 "/proc/tippe-test.csv" "no new file can be made" -- "${big[@]}" --csv /proc/tippe-test.csv
expect_fail "a missing directory" 2 "its directory does not exist" -- "${big[@]}" --csv "$d/none/x.csv"
expect_fail "a plot under /proc" 2 "/proc/self/x.png" -- "${big[@]}" --plot /proc/self/x.png
expect_fail "a plot into a directory" 2 "it is a directory" -- "${big[@]}" --plot "$d/adir.png"
expect_fail "two outputs that are one file" 2 "name the same file" -- \
    sweep "$m3" --plot "$d/same.png" --phase-plot "$d/./same.png"
ln -s same.png "$d/same-link.png"
expect_fail "two outputs that are one file through a link" 2 "name the same file" -- \
    sweep "$m3" --plot "$d/same.png" --phase-plot "$d/same-link.png"
expect_fail "simulate: a directory" 2 "it is a directory" -- simulate "$sc" --csv "$d/adir"
expect_fail "sweep: a plot through a file" 2 "Not a directory" -- sweep "$m3" --plot "$d/afile/z.png"
expect_fail "launch: a CSV under /proc" 2 "no new file" -- launch "$m3" --z2 4 -n 100000 --csv /proc/x.csv
cp "$sc" "$d/input.json"
ln -s input.json "$d/input-link.csv"
expect_fail "an output that is the input file" 2 "is the input file" -- \
    simulate "$d/input.json" --csv "$d/input.json"
expect_fail "an output that is the input file through a link" 2 "is the input file" -- \
    simulate "$d/input.json" --csv "$d/input-link.csv"
check "the input file is intact" cmp -s "$sc" "$d/input.json"
rm -f "$d/input-link.csv" "$d/input.json"
elapsed_ms=$((($(date +%s%N) - t0) / 1000000))
tippe=$real_tippe
rm -f "$d/same-link.png"
# 11 refusals, each well under a second even on a loaded machine; the work refused
# would take hours.
check "the refusals came before any work (${elapsed_ms} ms for 11)" test "$elapsed_ms" -lt 10000
check "the refusals left nothing on disk" test "$(ls -R "$d" | md5sum)" = "$before"
if [ "$(id -u)" -ne 0 ]; then
    mkdir -p "$d/ro"
    chmod 555 "$d/ro"
    expect_fail "an unwritable directory" 2 "Permission denied" -- "${big[@]}" --csv "$d/ro/x.csv"
    echo "read-only" >"$d/ro-file.csv"
    chmod 444 "$d/ro-file.csv"
    expect_fail "a read-only old file is not replaced" 2 "Permission denied" -- simulate "$sc" --csv "$d/ro-file.csv"
    chmod 755 "$d/ro"
else
    echo "test_io: root ignores permissions: unwritable-directory checks skipped"
fi

# --- defect 7: the duplicate-key check is not quadratic -------------------------
# 340k keys in 3.9 MiB (under the 4 MiB limit): refused for the unknown field in
# 0.2 s of CPU; the pairwise check took 207 s of CPU. 60 s is a 300-fold margin
# for a loaded machine, and still far below the old time.
python3 - "$d/many-keys.json" "$d/many-dup.json" "$d/order-dup.json" <<'EOF'
import sys
keys = ",".join('"k%06d":0' % i for i in range(340000))
open(sys.argv[1], "w").write('{"name":"many","extra":{%s}}' % keys)
open(sys.argv[2], "w").write('{"name":"many","extra":{%s,"k000007":1}}' % keys)
# 40 members (past the pairwise scan's 16): k30 repeats at member 35, k05 at 38;
# the walk in document order meets k30's repeat first.
m = ['"k%02d":0' % i for i in range(35)] + ['"k30":1', '"z1":0', '"z2":0', '"k05":1', '"z3":0']
open(sys.argv[3], "w").write('{"name":"order","extra":{%s}}' % ",".join(m))
EOF
t0=$(date +%s%N)
"$tippe" eval "$d/many-keys.json" --z2 0 >/dev/null 2>"$d/err" &
wait_or_kill $! 60
check "340k distinct keys: refused (exit 2) within 60 s" test "$waited" -eq 2
check "340k distinct keys: for the unknown field" grep -q "many-keys.json: extra: unknown field" "$d/err"
"$tippe" eval "$d/many-dup.json" --z2 0 >/dev/null 2>"$d/err" &
wait_or_kill $! 60
check "340k keys with one repeated: exit 2 within 60 s" test "$waited" -eq 2
check "340k keys with one repeated: names it" grep -q "many-dup.json: extra.k000007: duplicate key" "$d/err"
echo "test_io: the two 340k-key files took $((($(date +%s%N) - t0) / 1000000)) ms"
"$tippe" eval "$d/order-dup.json" --z2 0 >/dev/null 2>"$d/err"
check "the first repeat in document order is named" grep -q "order-dup.json: extra.k30: duplicate key" "$d/err"

# --- progress when stderr is not a terminal -------------------------------------
# Without --progress a log stays quiet; with it, plain lines "LABEL: DONE/TOTAL
# (PCT%), TIME" (no bar, no escape codes), ending with the "done in" line.
# (the M12: the M3's 0.167 g screw is warned about as a negligible moving weight)
"$tippe" launch designs/m12-setscrew.json --z2 10 -n 20 2>"$d/quiet.txt" >/dev/null
check "launch without --progress: nothing on a non-terminal stderr" test ! -s "$d/quiet.txt"
t0=$(date +%s%N)
# --t-end 20: the M3 stands on its rims (issue 35), where launches run to t_end
"$tippe" launch "$m3" --z2 4 -n 600 --t-end 20 --progress 2>"$d/progress-all.txt" >/dev/null
check "launch --progress exits 0" test $? -eq 0
ms=$((($(date +%s%N) - t0) / 1000000))
# the progress lines: all of stderr but the M3's warning (a negligible moving weight)
check "the M3's one warning is the negligible moving weight" \
    test "$(grep -c ': warning: ' "$d/progress-all.txt")" -eq 1 -a "$(grep -c 'the moving weight is' "$d/progress-all.txt")" -eq 1
grep -v ': warning: .*the moving weight is' "$d/progress-all.txt" >"$d/progress.txt"
# all_lines FILE REGEX: FILE has lines and every one matches REGEX.
all_lines() { [ -s "$1" ] && ! grep -qvE "$2" "$1"; }
check "every progress line is a plain 'done/total, time' line" all_lines "$d/progress.txt" \
    '^tippe launch: [0-9]+/600 \([0-9.]+%\), ([0-9].* left|done in .*|estimating time left)$'
check "progress lines carry no terminal escape or carriage return" \
    test "$(tr -d '\n' <"$d/progress.txt" | tr -d '[:print:]' | wc -c)" -eq 0
check "the last progress line is the whole work, done" \
    grep -qE '^tippe launch: 600/600 \(100.0%\), done in ' <(tail -1 "$d/progress.txt")
# A line is due every tenth of the work but at most every 2 s: a run of 5 s or
# more must have shown the work moving before it ended.
if [ "$ms" -ge 5000 ]; then
    check "a ${ms} ms run showed lines with the time left before the end" \
        grep -qE '^tippe launch: [0-9]+/600 .* left$' "$d/progress.txt"
else
    echo "test_io: launch took ${ms} ms (< 5 s): periodic progress lines not required"
fi
expect_fail "--progress on a verb without long work" 2 "unknown option '--progress'" -- \
    eval "$m3" --z2 4 --progress

finish
