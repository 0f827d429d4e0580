#!/usr/bin/env python3
"""The slicer rules of docs/slicer-rules.md, applied layer by layer to a ball with a through hole
or to a closed shell (axis vertical, printed whole), to check them against the G-code.

Not the print model: a direct transcription of the rules (walls = n spacing-wide bands from
(w - s)/2 inside each outline; infill region from d_f; solid infill where a layer's infill area
is not inside the infill region of every layer within k layers, grown by g, bands narrower than
1.05 s dropped; the first and last k layers solid; sparse = h (k_p f A + lambda L)). Prints the
walls, solid infill and sparse infill in grams at the given density.

    tools/slicer_rules_check.py ball HOLE_RADIUS_MM INFILL [--kp 0.932] [--lambda 0.17]
    tools/slicer_rules_check.py shell CAVITY_RADIUS_MM INFILL ...

e.g. `ball 5.5 0.15` (the M12 body: 18.10 g; its G-code 17.93 g), `shell 22.5 0.15` (16.36 g;
G-code 16.37 g). Defaults: R 25 mm, w 0.45 mm, h 0.2 mm, 2 perimeters, k 3, 25 % overlap,
density 1.08 g/cm^3 (ABSplus), gyroid (k_p 0.932, lambda 0.17 mm at 15 %; 0.923, 0.19 at 40 %).
"""
import argparse
import math


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("kind", choices=("ball", "shell"))
    ap.add_argument("inner_mm", type=float, help="hole radius (ball) or cavity radius (shell)")
    ap.add_argument("infill", type=float)
    ap.add_argument("--kp", type=float, default=0.932, help="pattern's bulk factor")
    ap.add_argument("--lambda", dest="lam", type=float, default=0.17, help="anchor band, mm")
    ap.add_argument("--R", type=float, default=25.0)
    ap.add_argument("--w", type=float, default=0.45)
    ap.add_argument("--h", type=float, default=0.2)
    ap.add_argument("--n", type=int, default=2)
    ap.add_argument("--k", type=int, default=3)
    ap.add_argument("--density", type=float, default=1.08)
    o = ap.parse_args()
    R, a, f, h, w, n, k = o.R, o.inner_mm, o.infill, o.h, o.w, o.n, o.k
    s = w - h * (1 - math.pi / 4)            # spacing: Flow::rounded_rectangle_extrusion_spacing
    e0 = (w - s) / 2                         # walls start here inside the outline
    df = e0 + n * s - 0.25 * s               # infill boundary (25 % infill_overlap of s)
    g = 0.3 * 1.05 * s                       # growth of the vertical-shell solid (opening)
    zmax = math.sqrt(R * R - a * a) if o.kind == "ball" else R
    N = int(round(2 * zmax / h))
    zs = [-zmax + (i + 0.5) * h for i in range(N)]  # slice planes: the middle of each layer

    def r_out(z):
        return math.sqrt(max(R * R - z * z, 0.0))

    def r_in(z):
        if o.kind == "ball":
            return a
        return math.sqrt(a * a - z * z) if abs(z) < a else 0.0

    def fill(i):
        if i < 0 or i >= N:
            return None
        fo, ri = r_out(zs[i]) - df, r_in(zs[i])
        fi = ri + df if ri > 0 else 0.0
        return (fi, fo) if fo > fi else None

    W = S = P = 0.0
    for i, z in enumerate(zs):
        ro, ri = r_out(z), r_in(z)
        if ro <= ri:
            continue
        ring = math.pi * (ro * ro - ri * ri)
        wall = math.pi * (ro * ro - max(ro - e0 - n * s, 0) ** 2)
        if ri > 0:
            wall += math.pi * ((ri + e0 + n * s) ** 2 - (ri + e0) ** 2)
        W += h * min(wall, ring)
        fr = fill(i)
        if fr is None:
            continue
        fi, fo = fr
        near = [fill(j) for j in range(i - k, i + k + 1)]
        sparse = None
        if all(x is not None for x in near):
            mo = min(x[1] for x in near)
            mi = max(x[0] for x in near)
            so = fo if fo - mo < 1.05 * s else mo - g
            si = fi if (fi == 0 or mi - fi < 1.05 * s) else mi + g
            if min(so, fo) > max(si, fi):
                sparse = (max(si, fi), min(so, fo))
        area = math.pi * (fo * fo - fi * fi)
        if sparse:
            A = math.pi * (sparse[1] ** 2 - sparse[0] ** 2)
            L = 2 * math.pi * (sparse[1] + sparse[0])
            S += h * (area - A)
            P += h * (o.kp * f * A + o.lam * L)
        else:
            S += h * area
    rho = o.density / 1000
    print(f"{o.kind} {a} mm, infill {f}: walls {W * rho:.2f} g, solid infill {S * rho:.2f} g, "
          f"sparse {P * rho:.2f} g, total {(W + S + P) * rho:.2f} g")


if __name__ == "__main__":
    main()
