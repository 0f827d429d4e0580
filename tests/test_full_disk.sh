#!/usr/bin/env bash
# A full disk while tippe build and tippe export write (issue 28, item 4): on a
# small tmpfs, at sizes from 50 kB to where everything fits, every run either
# succeeds or fails with exit 1 and a message naming the file and "No space
# left on device" (STL, 3MF, drawing, build sheet alike; the 3MF used to abort
# the process with exit 134 from inside lib3mf), and a failed run leaves no
# temporary ("*.tmp.*") and no output directory of its own behind. Needs to
# mount a tmpfs (root); skipped with a message where it cannot.
# Usage: test_full_disk.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
fs=$tmp/fs
mkdir "$fs"
mount -t tmpfs -o size=1200k tmpfs "$fs" 2>/dev/null ||
    skip "cannot mount a tmpfs here (needs root and CAP_SYS_ADMIN)"
trap 'umount "$fs" 2>/dev/null; rm -rf "$tmp"' EXIT
design=designs/m12-setscrew.json

# run VERB FROM STEP TO: VERB the design into a tmpfs of each size; the failures'
# files (their extension) are listed in $tmp/failed-VERB.
run() {
    local verb=$1 from=$2 step=$3 to=$4 kib
    : >"$tmp/failed-$verb"
    for ((kib = from; kib <= to; kib += step)); do
        rm -rf "${fs:?}"/*
        mount -o remount,size=${kib}k "$fs" || {
            bad "cannot resize the tmpfs to ${kib}k"
            return
        }
        "$tippe" "$verb" "$design" -o "$fs/out" >/dev/null 2>"$tmp/err"
        local st=$?
        local left
        left=$(find "$fs" -name '*.tmp.*')
        if [ "$st" -eq 0 ]; then
            check "$verb at ${kib}k: exit 0 and the files are there" test -s "$fs/out/m12-setscrew.3mf"
            continue
        fi
        local file
        file=$(sed -n "s|^tippe $verb: \($fs/out/[^:]*\): writing .* failed: No space left on device\$|\1|p" "$tmp/err")
        check "$verb at ${kib}k: exit 1, not $st ($(head -c 300 "$tmp/err"))" test "$st" -eq 1
        check "$verb at ${kib}k: the message names the file and 'No space left on device' ($(head -c 300 "$tmp/err"))" \
            test -n "$file"
        check "$verb at ${kib}k: no temporary left ($left)" test -z "$left"
        check "$verb at ${kib}k: no output directory left" test ! -e "$fs/out"
        echo "${file##*/}" >>"$tmp/failed-$verb"
    done
}
# failed_on VERB PATTERN: some run of VERB failed on a file matching PATTERN (grep -E).
failed_on() { grep -Eq "$2" "$tmp/failed-$1"; }

# tippe export: STL ~1.1 MB, then the 3MF (about 1.2-1.35 MB free aborted before), SCAD, drawings.
run export 50 50 1700
check "export: the STL's full disk was met" failed_on export '\.stl$'
check "export: the 3MF's full disk was met" failed_on export '\.3mf$'
check "export: the drawing's full disk was met" failed_on export 'section\.(svg|png|pdf)$'
# tippe build: the sheet (JSON, Markdown, PDF, SVG, PNG, gauges), then export's files
# (the 3MF at about 2.1-2.25 MB free aborted before; the section drawings, last, near 3 MB).
run build 50 50 3300
check "build: the sheet's full disk was met" failed_on build 'sheet\.(pdf|svg|png)$'
check "build: a gauge's or the body's STL full disk was met" failed_on build '\.stl$'
check "build: the 3MF's full disk was met" failed_on build '\.3mf$'
check "build: the section drawing's full disk was met" failed_on build 'section\.(svg|png|pdf)$'
echo "$test_name: failed files: export $(sort -u "$tmp/failed-export" | tr '\n' ' '); build $(sort -u "$tmp/failed-build" | tr '\n' ' ')"
finish
