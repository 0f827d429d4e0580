#!/bin/bash
# Each command reads each input file once (issue 34, "pass the design, not its
# path"): the design, its materials table, the catalogue, a scenario and the
# design it names are opened once however many variants a command builds (a
# sweep's tolerance bands derived 96 designs from the file, --vary N+2, the
# build sheet's advice 4958, a film 3: each read the file again). Counted with
# strace: every successful open of the file by the command and its threads.
source "$(dirname "$0")/lib.sh"
setup "$@"
command -v strace >/dev/null || skip "strace is not installed (tools/deps.sh installs it)"
strace -f -qq -o /dev/null true 2>/dev/null || skip "strace cannot trace here (no ptrace)"
m12=designs/m12-setscrew.json

# opens WHAT FILE... -- ARGS...: tippe ARGS succeeds and opens each FILE exactly once.
opens() {
    local what=$1 files=()
    shift
    while [ "$1" != "--" ]; do
        files+=("$1")
        shift
    done
    shift
    if ! strace -f -qq -e trace=openat -o "$tmp/trace" "$tippe" "$@" >"$tmp/out" 2>"$tmp/err"; then
        bad "$what: tippe $* failed: $(tail -3 "$tmp/err")"
        return
    fi
    local f n
    for f in "${files[@]}"; do
        # a successful open names the file in quotes and returns a descriptor
        n=$(grep -F "\"$f\"" "$tmp/trace" | grep -cv ' = -1 ')
        if [ "$n" -ne 1 ]; then
            bad "$what: $f opened $n times (once wanted)"
            return
        fi
    done
    ok
}

opens "sweep" "$m12" designs/materials.json -- sweep "$m12"
opens "sweep --vary" "$m12" designs/materials.json -- \
    sweep "$m12" --vary parts.screw.height_mm=5:20:4
opens "compare, one design" "$m12" designs/materials.json -- compare "$m12" --set 1:radius_mm=26
opens "animate DESIGN" "$m12" designs/materials.json -- \
    animate "$m12" --z2 10 --spin 60 --frame 0.5 -o "$tmp/m12.png"
opens "simulate DESIGN" "$m12" designs/materials.json -- \
    simulate "$m12" --z2 12 --spin 20rev/s --t-end 1 --accuracy fast
# a scenario naming a design: the scenario and the design once each (the film's
# weight is drawn from the scenario's design, not a second load)
printf '{"top": {"design": "%s/%s", "z2_mm": 10}, "mu": 2.3, "t_end": 2,
 "initial": {"theta": 0.1, "theta_dot": 0, "phi_dot": "steady", "spin": 60, "U": 0, "V": 0}}\n' \
    "$PWD" "$m12" >"$tmp/scenario.json"
opens "animate SCENARIO" "$tmp/scenario.json" "$PWD/$m12" "$PWD/designs/materials.json" -- \
    animate "$tmp/scenario.json" --frame 0.5 -o "$tmp/sc.png"
opens "build" "$m12" designs/materials.json designs/catalogue.json -- \
    build "$m12" -o "$tmp/sheet" --no-export
# an optimisation spec without "catalogue": the base design's (catalogue.json in its
# folder, the rule tippe build follows); spec, design, table and catalogue once each
cat >"$tmp/spec.json" <<SPEC
{"design": "$PWD/designs/drilled-ball-blind.json",
 "vary": {"parts.hole.z_mm": [10, 20]},
 "choose": {"parts.screw": {"catalogue": "iso4026", "items": ["M10x12"]},
            "parts.screw.material": ["iron", "brass"]},
 "tie": {"parts.hole.radius_mm": "parts.screw.radius_mm"},
 "search": {"evaluations": 12, "polish": "none"}}
SPEC
opens "optimise" "$tmp/spec.json" "$PWD/designs/drilled-ball-blind.json" \
    "$PWD/designs/materials.json" "$PWD/designs/catalogue.json" -- \
    optimise "$tmp/spec.json" -o "$tmp/best.json" --threads 1
# a printed part's G-code (megabytes), read once however many variants a sweep derives
# (37 reads before: each tolerance band's design read it again); sliced here by
# PrusaSlicer, when it is installed (CI installs it)
if command -v prusa-slicer >/dev/null &&
    "$tippe" slice designs/m12-setscrew-printed.json -o "$tmp/sl" >/dev/null 2>&1; then
    json_edit designs/m12-setscrew-printed.json "$tmp/sl/g.json" "
d['parts'][0]['print'] = {'gcode': 'm12-setscrew-printed.gcode'}
d['materials'] = '$PWD/designs/materials.json'"
    opens "sweep, a part's G-code" "$tmp/sl/g.json" "$tmp/sl/m12-setscrew-printed.gcode" -- \
        sweep "$tmp/sl/g.json"
else
    echo "test_read_once: the G-code check SKIPPED (no prusa-slicer to slice with)"
fi
finish
