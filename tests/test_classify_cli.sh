#!/usr/bin/env bash
# tippe classify as a user drives it: usage errors exit 2, --help exits 0, the text
# carries units, and --json is one parseable object whose fields agree with
# Theorem 5.1's inequalities for the paper's Figure 12 and 14 tops.
# Usage: bash tests/test_classify_cli.sh /path/to/tippe   (from the repo root)
source "$(dirname "$0")/lib.sh"
setup "$@"

# usage errors: exit 2, with a message naming the problem on stderr
check "no arguments" exits 2 classify
check "unknown option" exits 2 classify --A-over-C 0.9 --eps-over-R 0.3 --bogus
check "missing value" exits 2 classify --A-over-C 0.9 --eps-over-R
check "not a number" exits 2 classify --A-over-C abc --eps-over-R 0.3
check "trailing junk" exits 2 classify --A-over-C 0.9x --eps-over-R 0.3
check "eps/R = 1" exits 2 classify --A-over-C 0.9 --eps-over-R 1
check "negative eps/R" exits 2 classify --A-over-C 0.9 --eps-over-R -0.1
check "A/C = 0" exits 2 classify --A-over-C 0 --eps-over-R 0.3
check "nan" exits 2 classify --A-over-C nan --eps-over-R 0.3
check "--m without --R --C" exits 2 classify --A-over-C 0.9 --eps-over-R 0.3 --m 0.02
check "negative mass" exits 2 classify --A-over-C 0.9 --eps-over-R 0.3 --m -1 --R 0.02 --C 1e-6
check "zero g" exits 2 classify --A-over-C 0.9 --eps-over-R 0.3 --m 1 --R 1 --C 1 --g 0
"$tippe" classify --A-over-C 0.9 --eps-over-R 1.5 2>"$tmp/err" >/dev/null
check "error names the option" grep -q -- "--eps-over-R" "$tmp/err"

# --help
check "--help exits 0" exits 0 classify --help
"$tippe" classify --help >"$tmp/help"
check "--help shows usage" grep -q "^usage: tippe classify" "$tmp/help"
check "verb listed in tippe --help" bash -c "'$tippe' --help | grep -q classify"

# text output with units
"$tippe" classify --A-over-C 0.92 --eps-over-R 0.3 --m 0.02 --R 0.02 --C 3e-6 >"$tmp/text"
check "text exits 0" [ $? -eq 0 ]
check "text names the subgroup" grep -q "subgroup IIb" "$tmp/text"
check "text spins in rad/s and rev/s" grep -q "n-.*rad/s.*rev/s" "$tmp/text"
"$tippe" classify --A-over-C 0.55 --eps-over-R 0.5 >"$tmp/text2"
check "theta_b in deg and rad" grep -q "theta_b.*deg.*rad" "$tmp/text2"

# --json: one object; the fields obey the inequalities they came from
"$tippe" classify --A-over-C 0.92 --eps-over-R 0.3 --m 0.02 --R 0.02 --C 3e-6 --json >"$tmp/a.json"
check "json exits 0" [ $? -eq 0 ]
check "json parses, Figure 12 top is IIb" json_ok "$tmp/a.json" \
    "o['subgroup']=='IIb' and o['group']=='II' and o['boundary'] is None"
# IIb by the line: A/C - 1 > -(eps/R)^2, so b is not real and null
check "json: b null above the -e^2 line" json_ok "$tmp/a.json" \
    "o['A_over_C']-1 > -o['eps_over_R']**2 and o['b'] is None and o['theta_b_rad'] is None"
# n* = n+ (R + eps)/(R - eps), to printing precision (17 digits: 1e-14 is ample)
check "json: n* from n+" json_ok "$tmp/a.json" \
    "abs(o['n_star_rad_s'] - o['n_plus_rad_s']*(1+o['eps_over_R'])/(1-o['eps_over_R'])) < 1e-14*o['n_star_rad_s']"
check "json: thresholds positive" json_ok "$tmp/a.json" \
    "o['n_minus_rad_s']>0 and o['n_plus_rad_s']>0 and o['g_m_s2']>9.8"
"$tippe" classify --A-over-C 0.55 --eps-over-R 0.5 --json >"$tmp/b.json"
check "json: Figure 14 top is IIa with |b| < 1 and theta_b = acos b" json_ok "$tmp/b.json" \
    "o['subgroup']=='IIa' and abs(o['b'])<1 and abs(math.cos(o['theta_b_rad'])-o['b'])<1e-14"
check "json: no thresholds without m, R, C" json_ok "$tmp/b.json" "'n_minus_rad_s' not in o"
"$tippe" classify --A-over-C 1.5 --eps-over-R 0.3 --m 1 --R 1 --C 1 --json >"$tmp/c.json"
check "json: group III has no n+ (null) and theta_c = acos(c)" json_ok "$tmp/c.json" \
    "o['group']=='III' and o['subgroup']=='III' and o['n_plus_rad_s'] is None and o['n_star_rad_s'] is None and abs(math.cos(o['theta_c_rad'])-o['c'])<1e-14"
"$tippe" classify --A-over-C 0.7 --eps-over-R 0.3 --json >"$tmp/d.json"
check "json: boundary named and side documented (I)" json_ok "$tmp/d.json" \
    "o['boundary']=='A/C-1=-eps/R' and o['group']=='I' and o['theta_c_rad']==0"
"$tippe" classify --A-over-C 1 --eps-over-R 0 --m 1 --R 1 --C 1 --json >"$tmp/e.json"
check "json: balanced sphere, finite or null" json_ok "$tmp/e.json" \
    "o['boundary']=='eps/R=0' and all(v is None or isinstance(v,str) or math.isfinite(v) for v in o.values())"

finish
