#!/usr/bin/env bash
# Issue 36: a part's G-code (print.gcode) is read only from a regular file of at
# most 256 MiB. A device, a FIFO or a directory is refused at once with the
# design's field named; nothing blocks and nothing grows without bound.
source "$(dirname "$0")/lib.sh"
setup "$@"

d=$tmp/designs
mkdir -p "$d"
cp designs/materials.json "$d/"
with_gcode() { # with_gcode FILE GCODE: the printed M12 whose body's G-code is GCODE
    python3 - "$1" "$2" <<'PY'
import json, sys
d = json.load(open("designs/m12-setscrew-printed.json"))
d["parts"][0]["print"] = {"gcode": sys.argv[2]}
json.dump(d, open(sys.argv[1], "w"))
PY
}
mkfifo "$tmp/fifo"
mkdir "$tmp/dir"
for case in "zero:/dev/zero:a character device" "fifo:$tmp/fifo:a FIFO" "dir:$tmp/dir:a directory"; do
    IFS=: read -r name file kind <<<"$case"
    with_gcode "$d/$name.json" "$file"
    # timeout: a reader that blocked on the FIFO or read the zero device for ever
    # would be killed (exit 124) and fail the exit status check
    start=$(date +%s.%N)
    expect_fail "G-code from $kind" 2 "parts[0].print.gcode" "not a regular file ($kind)" -- \
        eval "$d/$name.json" --z2 10
    took=$(python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
    check "G-code from $kind: refused in ${took} s (< 5 s: it never read)" \
        python3 -c "import sys; sys.exit(not float(sys.argv[1]) < 5)" "$took"
done

# A regular file over the cap: a sparse file of 257 MiB costs no disk.
truncate -s 257M "$tmp/huge.gcode"
with_gcode "$d/huge.json" "$tmp/huge.gcode"
expect_fail "a 257 MiB G-code" 2 "parts[0].print.gcode" "more than the 256 MiB a G-code file" -- \
    eval "$d/huge.json" --z2 10
finish
