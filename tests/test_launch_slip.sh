#!/usr/bin/env bash
# The launch line says how the contact slips (issue 25.5): a central hand launch
# has its centre at rest (U = V = 0) but, tilted and precessing, its contact point
# slips at |V_Q| = |v + omega x q| (eq 3.7). check, simulate and animate print
# that slip, and "no sliding" only where it is 0 to rounding. The slip printed in
# --json equals |v + omega x q| computed here from the initial state and the top
# that simulate --json prints, to 1e-9 relative (both are a few products of
# numbers printed to 17 digits: ~1e-15); the text's 3 digits to 5e-3.
# Usage: test_launch_slip.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
d=designs/m12-setscrew.json

# slip JSON: |v + omega x q| from simulate --json's top and initial state
# (docs/dynamics.md, "The paper's variables": k, omega, v of (theta, ...)).
slip_of() {
    python3 - "$1" <<'PY'
import json, math, sys
o = json.load(open(sys.argv[1]))
t, i = o["top"], o["initial"]
R, eps = t["R_m"], t["eps_m"]
th, thd, al, n = i["theta_rad"], i["theta_dot_rad_s"], i["phi_dot_rad_s"], i["spin_rad_s"]
U, V = i["U_m_s"], i["V_m_s"]
s, c = math.sin(th), math.cos(th)
e1, e2, e3 = (1, 0, 0), (0, 1, 0), (0, 0, 1)
k = (s, 0, c)
ii = (c, 0, -s)
add = lambda *vs: tuple(sum(x) for x in zip(*vs))
mul = lambda a, v: tuple(a * x for x in v)
cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
w = add(mul(-al * s, ii), mul(thd, e2), mul(n, k))
q = add(mul(eps, k), mul(-R, e3))  # centre of mass to contact (eq 3.6)
vz = -eps * cross(w, k)[2]          # the height's rate (eq 3.11)
v = (U, V, vz)
VQ = add(v, cross(w, q))
print("%.17g %.17g" % (math.hypot(VQ[0], VQ[1]), abs(VQ[2])))
PY
}

"$tippe" simulate "$d" --z2 15 --json >"$tmp/sim.json" 2>"$tmp/err"
read -r want vz <<<"$(slip_of "$tmp/sim.json")"
check "V_Q is horizontal (eq 3.7 with the constraint): |V_Qz| $vz" \
    python3 -c "import sys; assert float(sys.argv[1]) < 1e-15" "$vz"
check "the central launch slips: |V_Q| = $want m/s, more than 1 cm/s" \
    python3 -c "import sys; assert float(sys.argv[1]) > 0.01" "$want"
check "simulate --json: contact_slip_m_s = |v + omega x q| to 1e-9" \
    json_ok "$tmp/sim.json" "abs(o['initial']['contact_slip_m_s'] - $want) <= 1e-9 * $want"
"$tippe" check "$d" --z2 15 --json >"$tmp/check.json" 2>"$tmp/err"
check "check --json: the same launch's contact_slip_m_s to 1e-9" \
    json_ok "$tmp/check.json" "abs(o['initial']['contact_slip_m_s'] - $want) <= 1e-9 * $want and o['initial']['U_m_s'] == 0 == o['initial']['V_m_s']"

# the text: the centre at rest, the contact's slip, never "no sliding"
"$tippe" check "$d" --z2 15 >"$tmp/check.txt" 2>&1
"$tippe" simulate "$d" --z2 15 >"$tmp/sim.txt" 2>&1
"$tippe" animate "$d" --z2 15 --frame 0.05 -o "$tmp/still.png" >"$tmp/anim.txt" 2>&1
for f in check sim anim; do
    check "$f: the launch line says centre at rest and the slip, not 'no sliding'" \
        python3 - "$tmp/$f.txt" "$want" <<'PY'
import re, sys
text, want = open(sys.argv[1]).read(), float(sys.argv[2])
assert "no sliding" not in text, "says no sliding"
m = re.search(r"centre at rest \(U = V = 0\), contact slip ([0-9.e+-]+) m/s", text)
assert m, "no slip in the launch line"
assert abs(float(m.group(1)) - want) <= 5e-3 * want, (m.group(1), want)
PY
done

# a launch whose contact is at rest: upright, spinning about the vertical
"$tippe" simulate "$d" --z2 15 --theta 0 >"$tmp/up.txt" 2>&1
check "upright spin: 'no sliding'" grep -q "no sliding (centre and contact at rest)" "$tmp/up.txt"
# rolling at launch: V chosen to cancel the contact's slip (V_QY = V + sin(theta)
# (eps phi_dot + R (n - phi_dot cos theta)), docs/dynamics.md "The reference form")
V=$(python3 -c "import sys; print(repr(-float(sys.argv[1])))" "$want")
"$tippe" simulate "$d" --z2 15 --V "$V" --json >"$tmp/roll.json" 2>"$tmp/err"
check "--V -slip: the contact is at rest to rounding (below 1e-12 of R |omega|)" \
    json_ok "$tmp/roll.json" "o['initial']['contact_slip_m_s'] < 1e-12 * 0.025 * 200"
"$tippe" simulate "$d" --z2 15 --V "$V" >"$tmp/roll.txt" 2>&1
check "--V -slip: the centre moves, 'no sliding (contact at rest)'" \
    grep -q "centre moving at .* no sliding (contact at rest)" "$tmp/roll.txt"
finish
