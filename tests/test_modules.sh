#!/usr/bin/env bash
# The command loads PLplot, GEOS, lib3MF and cairo only when a command needs them
# (src/modules/module.h): not linked, loaded with their module on first use, and a
# missing module is an error that names it; NLopt is opened by the optimiser itself.
# Usage: test_modules.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
bin=$(dirname "$tippe")
heavy='plplot|geos|3MF|cairo|nlopt'

# --- linked: none of the heavy libraries; each module links its own -----------
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
check "readelf lists what tippe needs" test -n "$(needed "$tippe")"
check "tippe links none of PLplot, GEOS, lib3MF, cairo, NLopt" \
    bash -c "! grep -Eq '$heavy' <<<'$(needed "$tippe")'"
for m in plot:plplot profile:geos_c export:3MF animate:cairo; do
    check "tippe-${m%%:*}.so sits next to tippe and links lib${m#*:}" \
        grep -q "^lib${m#*:}\.so" <<<"$(needed "$bin/tippe-${m%%:*}.so")"
done

# --- loaded: what each command needs, seen by the dynamic loader --------------
# loaded ARGS...: the files the loader opened for tippe ARGS (one per line).
loaded() {
    rm -f "$tmp"/ld.*
    LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$tippe" "$@" >/dev/null 2>&1 || return 1
    sed -n 's/.*file=\([^ ]*\) .*/\1/p' "$tmp"/ld.* | sort -u
}
check "simulate runs" loaded simulate designs/scenarios/fig12-tip.json >"$tmp/sim.libs"
check "simulate loads GSL (the loader's trace works)" grep -q libgsl "$tmp/sim.libs"
check "simulate loads no module and no heavy library" \
    bash -c "! grep -Eq 'tippe-|$heavy' '$tmp/sim.libs'"
check "sweep --plot runs" loaded sweep designs/m12-setscrew.json --plot "$tmp/z.png" \
    >"$tmp/plot.libs"
check "sweep --plot loads the plot module and PLplot" \
    bash -c "grep -q 'tippe-plot.so' '$tmp/plot.libs' && grep -q libplplot '$tmp/plot.libs'"
check "sweep --plot loads no lib3MF" bash -c "! grep -q 3MF '$tmp/plot.libs'"
check "eval runs" loaded eval designs/m12-setscrew.json --z2 15 >"$tmp/eval.libs"
check "eval loads GEOS for the printed bodies, not lib3MF or PLplot" \
    bash -c "grep -q libgeos_c '$tmp/eval.libs' && ! grep -Eq '3MF|plplot' '$tmp/eval.libs'"
check "optimise runs" loaded optimise tests/data/optimise-small.json -o "$tmp/best.json" \
    >"$tmp/opt.libs"
check "optimise opens NLopt" grep -q libnlopt "$tmp/opt.libs"

# --- missing or broken module: exit 1, the module named, no output file --------
mkdir -p "$tmp/alone"
cp "$tippe" "$tmp/alone/tippe"
tippe_alone=$tmp/alone/tippe
"$tippe_alone" simulate designs/scenarios/fig12-tip.json >"$tmp/sim.txt"
check "without modules simulate still works" test $? -eq 0
check "... and gives its verdict" grep -q "verdict" "$tmp/sim.txt"
# A plot's module is checked with its output path, before the work (exit 2, as
# for an unwritable plot): a map of 41 x 41 x 1000 launches would run for hours.
big_map="map designs/m12-setscrew.json --z2 0:20:41 --spin 2:30rev/s:41 -n 1000"
for case in "plot:2:sweep designs/m12-setscrew.json --plot $tmp/alone/z.png" \
            "plot:2:$big_map --plot $tmp/alone/m.png" \
            "export:1:export designs/shell-band.json -o $tmp/alone/print" \
            "animate:1:animate designs/scenarios/film-IIb-hang.json --frame 12.9 -o \
$tmp/alone/s.png"; do
    m=${case%%:*}
    rest=${case#*:}
    want=${rest%%:*}
    args=${rest#*:}
    # shellcheck disable=SC2086 # the arguments are words
    timeout 60 "$tippe_alone" $args >"$tmp/out" 2>"$tmp/err"
    st=$?
    check "without tippe-$m.so, ${args%% *} exits $want at once (got $st)" test $st -eq "$want"
    check "... naming tippe-$m.so" grep -q "cannot load $tmp/alone/tippe-$m.so" "$tmp/err"
done
outputs=("$tmp/alone/z.png" "$tmp/alone/m.png" "$tmp/alone/print" "$tmp/alone/s.png")
check "... and leaves no output behind" bash -c '! ls "$@" 2>/dev/null | grep -q .' _ "${outputs[@]}"
"$tippe_alone" eval designs/m12-setscrew.json --z2 15 >"$tmp/eval.txt"
check "without tippe-profile.so eval still gives the physics (exit 0)" test $? -eq 0
check "... and says why the printed bodies are missing" \
    grep -q "bodies .*cannot load .*tippe-profile.so" "$tmp/eval.txt"
echo "not a module" >"$tmp/alone/tippe-plot.so" # fault injection
"$tippe_alone" sweep designs/m12-setscrew.json --plot "$tmp/alone/z.png" >/dev/null 2>"$tmp/err"
st=$?
check "a broken tippe-plot.so: exit 2 (got $st)" test $st -eq 2
check "... naming it, with the loader's reason" \
    grep -q "cannot load .*tippe-plot.so.*: ." "$tmp/err"

finish
