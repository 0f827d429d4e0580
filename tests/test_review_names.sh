#!/bin/bash
# A run's title (simulate's scenario line, a film's caption) says first what
# differs between runs (the design's file and Z2) and shows changed numbers to
# 6 digits, not the exact 17 the command line passes on.
source "$(dirname "$0")/lib.sh"
setup "$@"
m12=designs/m12-setscrew.json

"$tippe" simulate "$m12" --z2 12 --spin 20rev/s --t-end 1 --accuracy fast --json >"$tmp/s.json"
check "simulate DESIGN: the name starts with the design's file and Z2" python3 -c "
import json,sys; n=json.load(open(sys.argv[1]))['name']
assert n.startswith('m12-setscrew.json at Z2 = 12 mm'), n
# 20 rev/s = 125.66370614359172 rad/s: shown to 6 digits in the title
assert 'initial.spin=125.664' in n and '125.6637061' not in n, n" "$tmp/s.json"
"$tippe" simulate "$m12" --z2 12 --t-end 1 --accuracy fast >"$tmp/s.txt"
check "a change that is not a number is listed as given" grep -q 'accuracy=fast\]' "$tmp/s.txt"
finish
