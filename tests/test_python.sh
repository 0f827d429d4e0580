#!/usr/bin/env bash
# python/tippe (ctypes over the build's libtippe.so): its numbers are the
# command's --json to the last digit (the JSON compared whole, parsed to the same
# doubles) for eval at mid-travel and sweep of every shipped design, for one
# central launch (check --json, its trajectory against --csv's 10 digits) and a
# batch's counts (launch --json); errors are exceptions with tippe's message.
# Usage: test_python.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
build=$(cd "$(dirname "$tippe")" && pwd)
tippe=$build/$(basename "$tippe")
py=/usr/bin/python3
if ! $py -c 'import numpy' 2>/dev/null; then
    echo "SKIPPED: Debian's python3-numpy is not installed (apt-get install python3-numpy)"
    exit 0
fi
export TIPPE_LIBRARY=$build/libtippe.so.0 PYTHONPATH=$PWD/python
for f in designs/*.json; do
    grep -q '"parts"' "$f" || continue
    read -r from to < <($py -c 'import json,sys; t=json.load(open(sys.argv[1]))["travel_mm"]; print(t["from"] if isinstance(t, dict) else t[0], t["to"] if isinstance(t, dict) else t[1])' "$f")
    z2=$($py -c "print(($from + $to) / 2)")
    "$tippe" eval "$f" --z2 "$z2" --json >"$tmp/eval.json" 2>/dev/null
    "$tippe" sweep "$f" --json >"$tmp/sweep.json" 2>/dev/null
    check "python eval and sweep of $f are the command's" $py - "$f" "$z2" "$tmp" <<'PY'
import json, sys, tippe
f, z2, tmp = sys.argv[1], float(sys.argv[2]), sys.argv[3]
d = tippe.load(f)
e, s = d.eval(z2), d.sweep().report
want_e, want_s = json.load(open(tmp + "/eval.json")), json.load(open(tmp + "/sweep.json"))
assert e == want_e, [k for k in want_e if e.get(k) != want_e[k]]
assert s == want_s, [k for k in want_s if s.get(k) != want_s[k]]
PY
done
f=designs/m12-setscrew.json
"$tippe" check "$f" --z2 15 --json >"$tmp/check.json"
"$tippe" check "$f" --z2 15 --csv "$tmp/check.csv" >/dev/null
check "python check is tippe check --json, its trajectory --csv's" $py - "$f" "$tmp" <<'PY'
import csv, json, sys, tippe
import numpy as np
f, tmp = sys.argv[1:]
r = tippe.check(f, 15)
want = json.load(open(tmp + "/check.json"))
assert r.report == want, [k for k in want if r.report.get(k) != want[k]]
rows = list(csv.DictReader(open(tmp + "/check.csv")))
assert len(rows) == len(r.t_s), (len(rows), len(r.t_s))
# --csv prints %.10g of the exact doubles; the binding's arrays come through cJSON,
# which prints a double with 15 digits when they read back within DBL_EPSILON
# (cJSON.c, print_number), so a value on a 10-digit tie can round either way: each
# value lies within half a unit of the CSV's 10th digit, plus 1e-15 of itself.
for col, arr in (("t_s", r.t_s), ("theta_rad", r.theta_rad), ("spin_rad_s", r.spin_rad_s)):
    exp = np.array([float(row[col]) for row in rows])
    mag = np.where(exp != 0, np.abs(exp), 1e-300)
    half_unit = 0.5 * 10.0 ** (np.floor(np.log10(mag)) - 9)
    bad = np.abs(arr - exp) > half_unit + 1e-15 * mag
    assert not bad.any(), (col, int(bad.sum()), np.flatnonzero(bad)[:3])
PY
"$tippe" launch "$f" --z2 15 -n 12 --seed 3 --json >"$tmp/launch.json" 2>/dev/null
check "python launch counts are tippe launch --json's" $py - "$f" "$tmp" <<'PY'
import json, sys, tippe
f, tmp = sys.argv[1:]
b = tippe.launch(f, 15, n=12, seed=3)
want = json.load(open(tmp + "/launch.json"))["counts"]
assert b.counts == want, (b.counts, want)
assert len(b.verdict) == 12 and sum(b.counts.values()) == 12
assert all(sum(b.verdict == v) == n for v, n in b.counts.items())
PY
check "a dict design with overrides is the file with --set" $py - "$f" <<'PY'
import json, sys, tippe
f = sys.argv[1]
a = tippe.load(json.load(open(f)), set=["parts.screw.height_mm=12"]).eval(10)
b = tippe.load(f, set=["parts.screw.height_mm=12"]).eval(10)
for k in ("mass_kg", "A_kg_m2", "C_kg_m2", "A_over_C", "eps_over_R"):
    assert a[k] == b[k], k
assert b["set"] == ["parts.screw.height_mm=12"]
PY
check "a bad override is a TippeError with tippe's message and field" $py - "$f" <<'PY'
import sys, tippe
try:
    tippe.load(sys.argv[1], set=["radius_mm=-3"])
except tippe.TippeError as e:
    assert e.code == 2 and e.field == "radius_mm" and "radius_mm: must be positive" in str(e), e
else:
    raise SystemExit("no exception")
PY
# pip install from the tree (Debian's pip, offline: no build isolation, no index),
# from a copy so that the build's litter stays out of the checkout
if $py -m pip --version >/dev/null 2>&1 && $py -c 'import setuptools, wheel' 2>/dev/null; then
    cp -r python "$tmp/src"
    $py -m pip install --no-build-isolation --no-deps --no-index --target "$tmp/site" "$tmp/src" \
        >"$tmp/pip.log" 2>&1
    check "pip install ./python" test $? -eq 0 || tail -5 "$tmp/pip.log"
    (cd "$tmp" && PYTHONPATH=$tmp/site $py -c 'import tippe, sys; assert tippe.__file__.startswith(sys.argv[1]); print(tippe.sweep(sys.argv[2]))' "$tmp/site" "$OLDPWD/$f") >"$tmp/pip.txt" 2>&1
    check "... and the module it installed runs" grep -Eq "^IIb +8\.689 +16\.360" "$tmp/pip.txt" || cat "$tmp/pip.txt"
else
    echo "SKIPPED: pip install ./python (python3-pip, python3-setuptools, python3-wheel)"
fi
finish
