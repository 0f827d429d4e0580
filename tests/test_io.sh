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

# nothing_left DIR: no temporary ("*.tmp.*") left in DIR.
nothing_left() { [ -z "$(find "$1" -name '*.tmp.*' -print -quit)" ]; }
# same_text FILE TEXT: FILE holds exactly TEXT (and a newline).
same_text() { [ "$(cat "$1")" = "$2" ]; }

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
cat "$d/pipe.csv" >"$d/from-pipe.csv" &
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

# "-" is standard output.
"$tippe" simulate "$sc" --csv - >"$d/stdout.txt"
check "--csv - exits 0" test $? -eq 0
check "--csv - writes the CSV to stdout" grep -qxF "$(head -1 "$d/ref.csv")" "$d/stdout.txt"
check "--csv - writes every row" test "$(grep -c '^[0-9]' "$d/stdout.txt")" -ge "$(($(wc -l <"$d/ref.csv") - 1))"
check "no file named '-' appears" test ! -e ./-

# --- defect 2: a failed write is an error, and the old file survives -----------
"$tippe" sweep "$m3" >/dev/full 2>"$d/err"
check "sweep > /dev/full exits 1" test $? -eq 1
check "sweep > /dev/full says why" grep -q "writing to standard output failed: No space left on device" "$d/err"

# A file-size limit (ulimit -f, in KiB; SIGXFSZ ignored so that write fails with
# EFBIG): the CSV is 3 MB, so 100 KiB cuts it short.
echo "old csv" >"$d/keep.csv"
(
    ulimit -f 100
    trap '' XFSZ
    "$tippe" simulate "$sc" --csv "$d/keep.csv" >/dev/null 2>"$d/err"
)
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
    (
        ulimit -f 20
        trap '' XFSZ
        "$tippe" simulate "$sc" --plot "$d/keep.$ext" >/dev/null 2>"$d/err"
    )
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
(
    ulimit -f 600
    trap '' XFSZ
    "$tippe" simulate "$sc" --sample-dt 1 --csv "$d/set.csv" --plot "$d/set.svg" >/dev/null 2>"$d/err"
)
check "simulate: a failed second output exits 1" test $? -eq 1
check "simulate: the first output's old file survives" same_text "$d/set.csv" "old csv"
check "simulate: the second output's old file survives" same_text "$d/set.svg" "old svg"
check "simulate: no temporary is left" nothing_left "$d"
# sweep: zone plot (PNG, ~100 kB) then phase plot (SVG, ~900 kB).
echo "old png" >"$d/zones.png"
echo "old svg" >"$d/phase.svg"
(
    ulimit -f 300
    trap '' XFSZ
    "$tippe" sweep "$m3" --plot "$d/zones.png" --phase-plot "$d/phase.svg" >/dev/null 2>"$d/err"
)
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
elapsed_ms=$((($(date +%s%N) - t0) / 1000000))
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

finish
