#!/usr/bin/env bash
# The shared option parser (src/cli/options.c) as a user meets it in every verb:
# "--opt=value" and "--opt value" mean the same, numbers may carry a unit of
# their option's family, out-of-range numbers are refused with the allowed
# range, and --help shows units and defaults. Usage: test_options_cli.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/m3-setscrew.json

# --opt=value and --opt value give the same report; 2cm is 20 mm.
"$tippe" eval "$d" --z2 20 --json >"$tmp/a.json" 2>&1
"$tippe" eval "$d" --z2=20 --json >"$tmp/b.json" 2>&1
"$tippe" eval --json "$d" --z2=2cm >"$tmp/c.json" 2>&1
check "--z2=20 and --z2 20 give the same JSON" cmp -s "$tmp/a.json" "$tmp/b.json"
# 2cm is converted to mm exactly (2 x 10): the same JSON to the last digit.
check "--z2 2cm is --z2 20" cmp -s "$tmp/a.json" "$tmp/c.json"

expect_fail "z2 out of range" 2 "--z2 '1e5'" "-1000 to 1000" "mm" -- eval "$d" --z2 1e5
expect_fail "z2 not a number" 2 "--z2 'abc'" -- eval "$d" --z2 abc
expect_fail "z2 unit of another family" 2 "--z2 '5rpm'" -- eval "$d" --z2 5rpm
expect_fail "z2 infinite" 2 "--z2 'inf'" -- eval "$d" --z2 inf
expect_fail "z2 NaN" 2 "--z2 'nan'" -- eval "$d" --z2 nan
expect_fail "missing value" 2 "--z2 needs a value" -- eval "$d" --z2
expect_fail "required option" 2 "--z2 MM is required" -- eval "$d"
expect_fail "flag with a value" 2 "--json=1 takes no value" -- eval "$d" --z2 5 --json=1
expect_fail "unknown option" 2 "unknown option '--frobnicate'" -- eval "$d" --z2 5 --frobnicate
# a unique prefix is the option (getopt_long), a prefix of two is refused naming both
check "--js is --json" json_ok <("$tippe" eval "$d" --z2 20 --js) "o['z2_mm'] == 20"
expect_fail "two design files" 2 "at most 1 design file" -- eval "$d" "$d" --z2 5
expect_fail "no design file" 2 "no design file given" -- eval --z2 5

"$tippe" eval --help >"$tmp/help" 2>&1
check "eval --help exits 0" test $? -eq 0
check "eval --help shows the unit and range of --z2" grep -q "\[mm; required; -1000 .. 1000\]" "$tmp/help"
check "eval --help names the unit suffixes" grep -q "2.5cm" "$tmp/help"
"$tippe" eval -h >"$tmp/help2" 2>&1
check "-h is --help" cmp -s "$tmp/help" "$tmp/help2"

finish
