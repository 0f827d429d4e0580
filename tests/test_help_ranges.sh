#!/usr/bin/env bash
# Every verb's --help tells the truth about its numbers (issue 19.10): each
# number an option's help shows as allowed ("[unit; default ...; MIN .. MAX]")
# is accepted at both ends, alone with the verb's defaults, and an option
# several verbs share has one range everywhere (spin: -M .. M where a signed
# spin makes sense, 0 .. M for hand launches, the same M).
#
# How "accepted" is seen without doing the work: the run names a design file
# that does not exist, so that a run whose options all pass stops at the file
# ("cannot open"), while a refused option stops before it, naming the option.
# Usage: test_help_ranges.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
nofile=$tmp/no-such-design.json

# verb and the arguments it needs besides the option under test
declare -A base=(
    [eval]="$nofile --z2 0" [sweep]="$nofile" [compare]="$nofile $nofile"
    [classify]="$nofile --z2 0" [simulate]="$nofile" [check]="$nofile --z2 0"
    [launch]="$nofile --z2 0" [map]="$nofile --z2 0:1:2 --spin 1:2:2"
    [animate]="$nofile -o $tmp/film.gif" [export]="$nofile -o $tmp/export"
    [optimise]="$nofile" [materials]="$nofile" [build]="$nofile -o $tmp/build" [slice]="$nofile -o $tmp/slice"
    [serve]="--designs $nofile"
)
# Options that only make sense with another (said in their help): given it too.
declare -A with=([export --split-z]="--split" [animate --frame]="-o $tmp/frame.png"
                 [check --radius-span]="--friction patch" [launch --radius-span]="--friction patch"
                 [map --radius-span]="--friction patch" [check --creep-cap]="--friction patch"
                 [launch --creep-cap]="--friction patch" [map --creep-cap]="--friction patch"
                 [build --creep-cap]="--friction patch" [animate --creep-cap]="--friction patch")
verbs=$("$tippe" --help | awk '/^  [a-z]+ /{print $1}')
check "tippe --help lists the verbs" test -n "$verbs"
# a verb not listed above gets the design file alone (give it a line if it needs more)
for v in $verbs; do
    [ -n "${base[$v]:-}" ] || base[$v]=$nofile
done

# "verb --option ARG unit min max" for every option whose help shows a range
for v in $verbs; do
    "$tippe" "$v" --help | python3 -c '
import re, sys
verb, cur = sys.argv[1], None
for line in sys.stdin.read().split("\n"):
    m = re.match(r"^  (?:-\w, )?(--[\w-]+)(?: (\S+))?", line)
    if m:
        cur = m.group(1), m.group(2) or ""
        continue
    m = re.match(r"^\s+\[(?:(.*); )?(-?[\d.e+]+) \.\. (-?[\d.e+]+)\]$", line)
    if m and cur:
        unit = (m.group(1) or "").split(";")[0] if m.group(1) and not m.group(1).startswith(("default", "required")) else ""
        print(verb, cur[0], cur[1], unit or "-", m.group(2), m.group(3))
        cur = None
' "$v"
done >"$tmp/opts"
check "the --help texts show ranges (more than 40 numeric options)" \
    test "$(wc -l <"$tmp/opts")" -gt 40

# Both ends of every advertised range are accepted.
while read -r v opt arg unit lo hi; do
    extra=${with["$v $opt"]-}
    # classify's numbers describe the top instead of a design file: tried below
    if [ "$v" = classify ] && [ "$opt" != --z2 ] && [ "$opt" != --g ]; then
        continue
    fi
    for x in "$lo" "$hi"; do
        # shellcheck disable=SC2086 # base and extra are word lists
        "$tippe" "$v" ${base[$v]} $extra "$opt=$x" >/dev/null 2>"$tmp/err"
        if grep -q "cannot open" "$tmp/err"; then
            ok
        else
            bad "tippe $v ${base[$v]} $extra $opt=$x (advertised $lo .. $hi) did not stop at the" \
                "missing file: $(head -1 "$tmp/err")"
        fi
    done
done <"$tmp/opts"

# classify with the numbers: each advertised end accepted (the others at defaults or 1)
while read -r v opt arg unit lo hi; do
    [ "$v" = classify ] && [ "$opt" != --z2 ] || continue
    for x in "$lo" "$hi"; do
        args=(--A-over-C 0.9 --eps-over-R 0.3)
        args+=("$opt=$x")
        "$tippe" classify "${args[@]}" >/dev/null 2>"$tmp/err"
        st=$?
        if [ $st -ne 2 ] || ! grep -q -- "$opt '" "$tmp/err"; then
            ok
        else
            bad "tippe classify $opt=$x (advertised $lo .. $hi) refused: $(head -1 "$tmp/err")"
        fi
    done
done <"$tmp/opts"

# One option name, one range: the verbs that share an option agree on it.
check "options several verbs share have one unit and range (signed spin: -M .. M)" \
    python3 - "$tmp/opts" <<'EOF'
import collections, sys
seen = collections.defaultdict(set)
for line in open(sys.argv[1]):
    verb, opt, arg, unit, lo, hi = line.split()
    lo, hi = float(lo), float(hi)
    if opt == "--spin" and lo == -hi:
        lo = 0.0          # a signed spin: the same magnitudes, either way round
    seen[opt].add((unit, lo, hi))
bad = {o: s for o, s in seen.items() if len(s) > 1}
for o, s in bad.items():
    print("differs:", o, sorted(s), file=sys.stderr)
sys.exit(1 if bad else 0)
EOF

finish
