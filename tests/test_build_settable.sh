#!/usr/bin/env bash
# tippe build's "settable" (issue 25.1): a behaviour is settable when its
# robust width is at least a quarter turn of the weight's thread (0.5 mm
# without a thread, or --min-setting-mm); the verdict "3-in-1 and settable" or
# "3-in-1 on paper only" in JSON, Markdown and on stderr's warnings; for flips
# and hangs, the part of the range whose needed spin a hand reaches (5 .. 25
# rev/s), checked against tippe classify's thresholds at its ends.
# Usage: test_build_settable.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

# --- the M12: its hangs range is 0.11 mm, below a quarter turn (1.75 / 4) -----
d=designs/m12-setscrew.json
"$tippe" build "$d" -o "$tmp/m12" --no-export --json >"$tmp/m12.json" 2>"$tmp/m12.err"
check "M12 builds" test -s "$tmp/m12.json"
check "M12: 3-in-1 on paper only, the rule a quarter turn of M12 x 1.75" \
    json_ok "$tmp/m12.json" 'o["three_in_one"] and not o["settable"] and o["verdict"] == "3-in-1 on paper only" and abs(o["min_setting_mm"] - 1.75 / 4) < 1e-12 and "quarter turn" in o["min_setting_rule"]'
check "M12: each setting's settable is its robust width against 0.4375 mm" \
    json_ok "$tmp/m12.json" 'all(s["settable"] == (s["robust_width_mm"] >= 1.75 / 4) for s in o["settings"]) and [s["settable"] for s in o["settings"]] == [True, True, False]'
# (the other warning, contact INVALID at the poles, is test_build_poles')
check "M12: one width warning, on hangs, with its width and the limit" \
    json_ok "$tmp/m12.json" '[w for w in o["warnings"] if "robust range" in w] == [o["warnings"][0]] and "hangs" in o["warnings"][0] and "0.11 mm" in o["warnings"][0] and "0.44 mm" in o["warnings"][0] and not any("stays up setting" in w for w in o["warnings"])'
check "M12: the warning on stderr too" grep -q "tippe build: warning: .*hangs" "$tmp/m12.err"
"$tippe" build "$d" -o "$tmp/m12md" --no-export >"$tmp/m12.md" 2>/dev/null
check "M12: the Markdown says 3-in-1 on paper only" grep -q "3-in-1 on paper only" "$tmp/m12.md"
check "M12: the Markdown file (the sheet) has the warning" grep -q "Warning.*hangs" "$tmp/m12md/m12-setscrew-build.md"
check "M12: the sheet's page is written" test -s "$tmp/m12md/m12-setscrew-sheet.pdf"

# --- --min-setting-mm: below every width, it is settable ----------------------
"$tippe" build "$d" -o "$tmp/m12b" --no-export --json --min-setting-mm 0.1 >"$tmp/m12b.json" 2>"$tmp/m12b.err"
check "M12 --min-setting-mm 0.1: 3-in-1 and settable, no warning" \
    json_ok "$tmp/m12b.json" 'o["settable"] and o["verdict"] == "3-in-1 and settable" and o["min_setting_mm"] == 0.1 and "--min-setting-mm" in o["min_setting_rule"] and not any("narrower than" in w and "robust range" in w for w in o["warnings"])'
check "M12 --min-setting-mm 0.1: no settable warning on stderr" bash -c '! grep -q "robust range.*narrower" "$1"' _ "$tmp/m12b.err"
"$tippe" build "$d" -o "$tmp/m12c" --no-export >"$tmp/m12c.md" --min-setting-mm 0.1 2>/dev/null
check "M12 --min-setting-mm 0.1: the Markdown says 3-in-1 and settable" grep -q "3-in-1 and settable" "$tmp/m12c.md"
expect_fail "--min-setting-mm 0 refused" 2 "--min-setting-mm" -- build "$d" -o "$tmp/x0" --min-setting-mm 0
expect_fail "--min-setting-mm -1 refused" 2 "--min-setting-mm" -- build "$d" -o "$tmp/x1" --min-setting-mm -1
check "no directory left by a refusal" test ! -e "$tmp/x0" -a ! -e "$tmp/x1"

# --- not 3-in-1: the verdict says so, whatever the widths ----------------------
"$tippe" build designs/m12-setscrew-printed.json -o "$tmp/m12p" --no-export --json >"$tmp/m12p.json" 2>/dev/null
check "printed M12: not 3-in-1, not settable" \
    json_ok "$tmp/m12p.json" 'not o["three_in_one"] and not o["settable"] and o["verdict"] == "not 3-in-1"'

# --- no thread: 0.5 mm ---------------------------------------------------------
# (shell-band-best's rod, 7.02 mm across, is no ISO 261 size)
"$tippe" build designs/shell-band-best.json -o "$tmp/band" --no-export --json >"$tmp/band.json" 2>/dev/null
check "shell-band-best (no thread): the limit is 0.5 mm, flips (0.19 mm) too narrow" \
    json_ok "$tmp/band.json" 'not o["thread"] and o["min_setting_mm"] == 0.5 and "no thread" in o["min_setting_rule"] and all(s["settable"] == (s["robust_width_mm"] >= 0.5) for s in o["settings"] if s["reachable"]) and o["verdict"] == "3-in-1 on paper only" and any("flips" in w and "0.19 mm" in w for w in o["warnings"])'

# --- the part of flips' and hangs' ranges a hand's spin reaches ----------------
# within the range; at an end inside the range the needed spin is the hand's
# 25 rev/s (classify's max(n-, n*) for flips, n- for hangs); inside it at most 25
python3 - "$tmp/m12.json" >"$tmp/ends" <<'EOF' && ok || bad "M12: hand parts not within the ranges"
import json, sys
o = json.load(open(sys.argv[1]))
for f, s in enumerate(o["settings"]):
    if f == 0:
        assert s.get("hand_z2_from_mm") is None, s
        continue
    a, b = (s["robust_from_mm"], s["robust_to_mm"]) if s["robust"] else (s["z2_from_mm"], s["z2_to_mm"])
    lo, hi = s["hand_z2_from_mm"], s["hand_z2_to_mm"]
    assert a - 1e-12 <= lo < hi <= b + 1e-12, (a, b, lo, hi)
    for z, end in ((lo, a), (hi, b)):
        print(f, z, int(abs(z - end) > 1e-9))
    print(f, 0.5 * (lo + hi), 0)
EOF
while read -r f z inner; do
    "$tippe" classify "$d" --z2 "$z" --json >"$tmp/c.json"
    python3 - "$tmp/c.json" "$f" "$inner" <<'EOF' && ok || bad "M12: the hand part's end at Z2 $z (family $f) is not where the needed spin is 25 rev/s"
import json, math, sys
c = json.load(open(sys.argv[1])); f = int(sys.argv[2]); inner = int(sys.argv[3])
nm = c["n_minus_rad_s"] or 0
n = max(nm, c["n_star_rad_s"]) if f == 1 else nm
n /= 2 * math.pi
assert n <= 25 + 1e-3, n
if inner:
    assert abs(n - 25) < 1e-3, n
EOF
done <"$tmp/ends"
check "M12: flips' hand part leaves out the end that needs 29.9 rev/s" \
    json_ok "$tmp/m12.json" '(s := o["settings"][1])["spin_needed_max_rev_s"] > 29 and s["hand_z2_to_mm"] - s["hand_z2_from_mm"] < s["robust_width_mm"] - 0.1'
check "M12: the hand part as depths from the rim (the depth of its Z2 ends)" \
    json_ok "$tmp/m12.json" '(s := o["settings"][1]) and (r := o["measure"]["reference_z_mm"]) and (e := o["measure"]["weight_end_above_z2_mm"]) and abs(s["hand_depth_from_mm"] - (r - s["hand_z2_from_mm"] - e)) < 1e-9 and abs(s["hand_depth_to_mm"] - (r - s["hand_z2_to_mm"] - e)) < 1e-9'
check "M12: the Markdown's flips row gives the hand's depths" \
    grep -q "^| flips .*a hand (up to 25 rev/s) reaches it at depth" "$tmp/m12.md"
# --- issue 37: a zone cut by the design's own travel_mm, not by the physics -----------
# drilled-ball-blind is settable over its parts' travel (-7.5 .. 16.887 mm); stated only to
# 13 mm its hangs range is cut: the advice's first change is the travel out to what the
# parts allow (nothing to buy), and that change is settable
"$tippe" build designs/drilled-ball-blind.json --set "travel_mm=[-7.5,13]" -o "$tmp/short" \
    --no-export --json >"$tmp/short.json" 2>/dev/null
check "travel cut at 13 mm: on paper only, the first change the travel to the parts' limit" \
    json_ok "$tmp/short.json" 'o["verdict"] == "3-in-1 on paper only" and o["to_make_it_settable"][0]["set"][0].startswith("travel_mm=[-7.5,16.887") and o["to_make_it_settable"][0]["settable"] and "nothing to buy" in o["to_make_it_settable"][0]["advice"]'
check "M12: its hangs cut by the physics (the screw out of the ball), not its travel: no travel change" \
    json_ok "$tmp/m12.json" 'not any(a["set"][0].startswith("travel_mm") for a in o["to_make_it_settable"])'
finish
