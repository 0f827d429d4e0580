#!/usr/bin/env python3
"""Independent check of a drilled-ball design's zones (no tippe code): a solid ball of
radius R with a blind hole of radius a from its floor z0 up through the surface, and a
cylindrical screw of radius a and height h moving in it. Mass moments by Simpson's rule
over z (every integrand is a polynomial on each piece, so the rule is exact to
rounding), the travel in closed form (screw on the floor; its top corner on the sphere),
groups by Theorem 5.1 (I: A/C - 1 < -eps/R, III: A/C - 1 > eps/R, II between), zone ends
by bisection to 1e-10 mm. Usage: check_drilled_ball.py DESIGN.json; prints the widest run
of each group and the narrowest, in mm."""
import json, math, os, sys

def simpson(f, a, b, n=2000):
    if b <= a:
        return 0.0
    h = (b - a) / n
    s = f(a) + f(b) + sum((4 if i % 2 else 2) * f(a + i * h) for i in range(1, n))
    return s * h / 3

def main(path):
    d = json.load(open(path))
    mats = json.load(open(os.path.join(os.path.dirname(path), d.get("materials", "materials.json"))))
    parts = {p["name"]: p for p in d["parts"]}
    body, hole, screw = parts["body"], parts["hole"], parts["screw"]
    R = d["radius_mm"]
    a, zh, hh = hole["radius_mm"], hole["z_mm"], hole["height_mm"]
    assert hole.get("clip") == "sphere" and zh + hh / 2 >= R, "a hole open at the top"
    rb = mats[body["material"]]["density_g_cm3"]
    rs = mats[screw["material"]]["density_g_cm3"]
    z0 = zh - hh / 2                     # the hole's floor
    zc = math.sqrt(R * R - a * a)        # above it the hole takes the sphere's whole disc
    # Fixed body: at height z a disc of radius^2 R^2 - z^2, less the hole's disc
    # (radius^2 a^2, or the whole disc above zc). Which applies is decided per
    # piece at its middle, so that no piece's end takes the other side's value.
    mom = [0.0] * 4  # m, m_z, m_zz, m_rr (g/cm^3 * mm^n; units cancel in k, e)
    brk = sorted({-R, R, max(-R, min(R, z0)), zc, -zc})
    for lo, hi in zip(brk, brk[1:]):
        mid = 0.5 * (lo + hi)
        inner = (lambda z: 0.0) if mid < z0 else \
                (lambda z: R * R - z * z) if mid > zc else (lambda z: a * a)
        ann = lambda z: (R * R - z * z) - inner(z)
        ann2 = lambda z: (R * R - z * z) ** 2 - inner(z) ** 2
        for i, g in enumerate((lambda z: 1, lambda z: z, lambda z: z * z)):
            mom[i] += rb * math.pi * simpson(lambda z: g(z) * ann(z), lo, hi)
        mom[3] += rb * math.pi / 2 * simpson(ann2, lo, hi)
    ra, h = screw["radius_mm"], screw["height_mm"]
    ms = rs * math.pi * ra * ra * h
    def ke(z2):
        m = mom[0] + ms
        mz = mom[1] + ms * z2
        mzz = mom[2] + ms * (z2 * z2 + h * h / 12)
        mrr = mom[3] + ms * ra * ra / 2
        zcm = mz / m
        A = mrr / 2 + mzz - m * zcm * zcm
        return A / mrr, abs(zcm) / R
    def fam(z2):
        k, e = ke(z2)
        return 0 if k - 1 < -e else 2 if k - 1 > e else 1
    lo, hi = z0 + h / 2, math.sqrt(R * R - ra * ra) - h / 2   # closed-form travel
    n = 20000
    zs = [lo + (hi - lo) * i / n for i in range(n + 1)]
    cuts, prev = [lo], fam(lo)
    for x0, x1 in zip(zs, zs[1:]):
        f1 = fam(x1)
        if f1 != prev:
            u, v = x0, x1
            while v - u > 1e-10:
                w = 0.5 * (u + v)
                if fam(w) == prev:
                    u = w
                else:
                    v = w
            cuts.append(0.5 * (u + v))
            prev = f1
    cuts.append(hi)
    widest = [0.0, 0.0, 0.0]
    for u, v in zip(cuts, cuts[1:]):
        f = fam(0.5 * (u + v))
        widest[f] = max(widest[f], v - u)
    print("travel %.9f .. %.9f mm" % (lo, hi))
    print("zones I %.9f II %.9f III %.9f narrowest %.9f mm" % (*widest, min(widest)))

if __name__ == "__main__":
    main(sys.argv[1])
