#!/usr/bin/env bash
# The patch law's creep reduced against the full law and the viscous law, side by side in
# one run, CPU time (issue 38; docs/performance.md, "The patch law at the viscous law's
# price"). A benchmark, not a test: it prints a table and asserts nothing.
#   tools/bench/creep_reduced.sh [BUILD_DIR]        (default build; ~6 min on one core)
set -euo pipefail
B=${1:-build}/tippe
D=designs/m12-setscrew.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cpu() { /usr/bin/time -f "%U" -o "$tmp/cpu" "$@" > "$tmp/out" 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }; cat "$tmp/cpu"; }
field() { python3 -c "import json,sys; d=json.load(open('$tmp/out')); print(d.get('$1'))"; }
laws=("viscous:--friction viscous" "reduced:--friction patch" "full:--friction patch --creep-cap 0")

echo "# one launch to t_end = 600 s (tippe simulate --full), M12 central hand launch at 15 rev/s"
printf "%-6s %-8s %10s %10s %9s %12s %8s\n" z2_mm law t_flip_s t_fall_s verdict rhs_evals cpu_s
for z in 5 10 15; do
  for l in "${laws[@]}"; do
    c=$(cpu $B simulate $D --z2 $z --full --t-end 600 --json ${l#*:})
    printf "%-6s %-8s %10.6s %10.6s %9s %12s %8s\n" $z ${l%%:*} "$(field t_flip_s)" \
      "$(field t_fall_s)" "$(field verdict)" "$(field rhs_evals)" "$c"
  done
done

echo "# 40 hand launches at Z2 = 10 mm, t_end 600 s, one thread (tippe launch -n 40)"
printf "%-8s %-34s %-30s %12s %8s\n" law counts passed_pi_2/fell_back medians_s cpu_s
for l in "${laws[@]}"; do
  c=$(cpu $B launch $D --z2 10 -n 40 --threads 1 --no-radius-sensitivity --json ${l#*:} 2>/dev/null || \
      cpu $B launch $D --z2 10 -n 40 --threads 1 --json ${l#*:})
  python3 - "$tmp/out" "${l%%:*}" "$c" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); c = d['counts']
f = lambda x: '-' if x is None else '%.4g' % x
print('%-8s %-34s %-30s %12s %8s' % (sys.argv[2],
      'no_tip %d tip %d hang %d' % (c['no_tip'], c['tip'], c['hang']),
      '%d / %d' % (d['passed_pi_2'], d['fell_back']),
      '%s / %s' % (f(d['median_t_passed_s']), f(d['median_t_fall_s'])), sys.argv[3]))
PY
done

echo "# the page's patch check: tippe check at Z2 = 10 mm with its three radii"
for l in "reduced:--friction patch" "full:--friction patch --creep-cap 0"; do
  c=$(cpu $B check $D --z2 10 --json ${l#*:})
  printf "%-8s verdict %-8s cpu_s %s\n" ${l%%:*} "$(field verdict)" "$c"
done
