#!/usr/bin/env bash
# Poles where the surface is not the sphere (issue 25.7): a hole that opens at a pole removes
# the cap within asin(r / R) of it, where a tilted top stands on the hole's rim. The M12's
# through hole (r 5.5 mm, R 25 mm) opens both poles; the blind hole only its open end; the
# band shell neither. The half-angle is the closed form to rounding (1e-12).
source "$(dirname "$0")/lib.sh"
setup "$@"

"$tippe" eval designs/m12-setscrew.json --z2 10 --json >"$tmp/m12.json"
check "M12: both poles open, 12.7 degrees" json_ok "$tmp/m12.json" \
    "len(o['polar_caps']) == 2 and all(abs(c['half_angle_rad'] - math.asin(5.5 / 25)) < 1e-12 and c['opening_mm'] == 11 for c in o['polar_caps'])"
"$tippe" eval designs/drilled-ball-blind.json --z2 0 --json >"$tmp/blind.json"
check "blind hole: only its open pole" json_ok "$tmp/blind.json" \
    "[c['pole'] for c in o['polar_caps']] == ['+z']"
"$tippe" eval designs/shell-band.json --z2 5 --json >"$tmp/band.json"
check "band shell: the sphere is whole" json_ok "$tmp/band.json" "o['polar_caps'] == []"
"$tippe" eval designs/m12-setscrew.json --z2 10 >"$tmp/m12.txt"
check "eval says which pole the top stands on upright" grep -q \
    "^pole     +z: the opening of 'hole' (11.00 mm): tilted less than 12.7 deg .*the pole it stands on at theta = 0" "$tmp/m12.txt"
# check: the M12's hand launch (3.9 deg) starts within its resting pole's opening, and a flip
# ends on the other pole's (inverted, 0 deg from it); the blind ball's inverted pole is whole
# (the sphere's model, --sphere-contact, tips it onto the -z pole; on its rims it hangs)
"$tippe" check designs/m12-setscrew.json --z2 10 --sphere-contact --json >"$tmp/c10.json"
check "check: a flip starts and ends on the M12's openings" json_ok "$tmp/c10.json" \
    "o['verdict'] == 'tip' and o['on_polar_cap']['start'] == '+z' and o['on_polar_cap']['end'] == '-z'"
"$tippe" check designs/m12-setscrew.json --z2 10 --json >"$tmp/c10r.json"
check "check on the rims: starts on +z, the verdict observed (J changes on a rim)" json_ok "$tmp/c10r.json" \
    "o['on_polar_cap']['start'] == '+z' and o['decided_by'] in ('observed', 'energy_cone', 'trapped')"
"$tippe" check designs/m12-setscrew.json --z2 10 >"$tmp/c10.txt"
check "check says so in words" grep -q "^pole       the launch starts 3.9 deg from the +z pole" "$tmp/c10.txt"
# sweep names the open poles too, in words and JSON (issue 25.7: eval, sweep, check, the sheet)
"$tippe" sweep designs/m12-setscrew.json --json >"$tmp/sw.json" 2>/dev/null
check "sweep: the M12's two open poles, asin(5.5/25)" json_ok "$tmp/sw.json" \
    "sorted(c['pole'] for c in o['polar_caps']) == ['+z', '-z'] and all(abs(c['half_angle_rad'] - __import__('math').asin(0.22)) < 1e-12 for c in o['polar_caps'])"
check "sweep says so in words" bash -c '"$1" sweep designs/m12-setscrew.json 2>/dev/null | grep -q "^pole     +z: the opening of .hole. (11.00 mm across)"' _ "$tippe"
"$tippe" sweep designs/shell-band.json --json >"$tmp/swb.json" 2>/dev/null
check "sweep: the band shell has no open pole" json_ok "$tmp/swb.json" "o['polar_caps'] == []"
finish
