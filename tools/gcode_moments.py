#!/usr/bin/env python3
"""Independent check of tippe's G-code reader (src/gcode*.c), sharing no code with it.

Reads an FFF G-code file (PrusaSlicer, SuperSlicer, OrcaSlicer, Cura) with the same
rules as the reader (include/tippe/print.h: E relative under M83 or G91; G92 renames
axes; a retraction deposits nothing and is owed, a positive dE first pays back what is
owed; features from ;TYPE: / ; FEATURE: labels; skirt, brim, support, towers, custom and
-- in a labelled file -- unlabelled G-code excluded), but integrates the moments another
way: every bead is a w x h box below the nozzle (h from ;HEIGHT:, else the height above
the last level below; w = volume / (length h)), and its mass moments are summed by
Gauss-Legendre quadrature over the box (2 points along, across and up: exact for the
quadratic integrands); arcs (G2/G3) are integrated along the true arc (8 Gauss points
per chord of at most 2 degrees) instead of along chords. --line gives thin rods at the
nozzle (1 Gauss point across and up, no shift).

Usage: gcode_moments.py FILE.gcode [--diameter MM] [--density G_CM3] [--override]
                         [--volumetric 0|1] [--line] [--json]
Prints the body's mass, volume, centre of mass, inertia tensor about it (bed frame), the
part's frame (axis through the footprint's centre, z from the bottom: z_cm, A, C) and the
volume of each feature. Needs numpy (Debian: python3-numpy)."""
import bisect, json, math, re, sys

import numpy as np

BODY = ["external perimeter", "perimeter", "solid infill", "top solid infill", "bridge infill",
        "sparse infill", "gap fill", "other"]
EXCLUDED = ["skirt/brim", "support", "support interface", "wipe tower", "custom", "unlabelled"]
LABELS = {
    "external perimeter": 0, "outer wall": 0, "wall-outer": 0,
    "perimeter": 1, "internal perimeter": 1, "overhang perimeter": 1, "inner wall": 1,
    "overhang wall": 1, "thin wall": 1, "wall-inner": 1,
    "solid infill": 2, "internal solid infill": 2, "bottom surface": 2, "skin": 2,
    "top solid infill": 3, "top surface": 3,
    "bridge infill": 4, "internal bridge infill": 4, "bridge": 4, "internal bridge": 4,
    "internal infill": 5, "sparse infill": 5, "fill": 5,
    "gap fill": 6, "gap infill": 6,
    "skirt/brim": 8, "skirt": 8, "brim": 8,
    "support material": 9, "support": 9, "support transition": 9, "support-infill": 9,
    "support material interface": 10, "support interface": 10, "support-interface": 10,
    "support-roof": 10,
    "wipe tower": 11, "prime tower": 11, "prime-tower": 11,
    "custom": 12,
}
CUSTOM, UNLABELLED = 12, 13
NAMES = BODY + EXCLUDED
WORD = re.compile(r"([A-Za-z])([-+]?(?:\d+\.?\d*|\.\d+))?")


def config(lines):
    """The slicer's comments: diameter and density lists, volumetric E, labels, Cura."""
    c = {"diam": None, "dens": None, "vol": None, "labelled": False, "cura": False}
    for raw in lines:
        s = raw.strip()
        if not s.startswith(";"):
            continue
        s = s[1:].strip()
        m = re.match(r"(filament_diameter|filament_density|use_volumetric_e)\s*[=:]\s*(.*)$", s)
        if m:
            vals = [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)", m.group(2))]
            key = {"filament_diameter": "diam", "filament_density": "dens",
                   "use_volumetric_e": "vol"}[m.group(1)]
            if key == "vol":
                c["vol"] = bool(vals and vals[0])
            elif vals and vals[0] > 0 and c[key] is None:
                c[key] = vals
        elif s.startswith("TYPE:") or s.startswith("FEATURE:"):
            c["labelled"] = True
        elif s.startswith("FLAVOR:") or (s.startswith("Generated with") and "Cura" in s):
            c["cura"] = True
    return c


def per_tool(lst, t, opt, override):
    if opt and (override or not lst):
        return opt
    if not lst:
        return None
    return lst[min(t, len(lst) - 1)]


def read(path, args):
    text = open(path, "rb").read().decode("utf-8", "replace")
    lines = text.split("\n")
    cfg = config(lines)
    rho = per_tool(cfg["dens"], 0, args["density"], args["override"])
    if not rho:
        sys.exit(f"{path}: no filament density (give --density)")
    vol_e = cfg["vol"] if args["volumetric"] is None else args["volumetric"]
    vol_e = bool(vol_e)
    pos = [0.0, 0.0, 0.0]
    off = [0.0, 0.0, 0.0]
    e = 0.0
    rel, m83, tool, flow = False, False, 0, 1.0
    owed = {}
    feature = UNLABELLED
    height = 0.0
    levels = []          # nozzle heights of deposits that count for the fallback
    segs = []            # (kind, p0, p1, centre, vol, h, feature, rho) ; kind 0 line, 1 arc
    for raw in lines:
        s = raw.strip()
        if s.startswith(";"):
            c = s[1:].strip()
            if c.startswith("TYPE:") or c.startswith("FEATURE:"):
                feature = LABELS.get(c.split(":", 1)[1].strip().lower(), 7)
            elif c.startswith("HEIGHT:") or c.startswith("LAYER_HEIGHT:"):
                try:
                    height = float(c.split(":", 1)[1])
                except ValueError:
                    pass
            elif cfg["cura"] and c.startswith("TIME_ELAPSED:"):
                feature = UNLABELLED
            continue
        s = s.split(";", 1)[0]
        s = re.sub(r"\(.*?\)", " ", s)
        s = s.split("*", 1)[0].strip()
        if not s:
            continue
        words = WORD.findall(s)
        if words and words[0][0].upper() == "N":
            words = words[1:]
        if not words or not words[0][1]:
            continue
        cmd = words[0][0].upper() + words[0][1]
        w = {k.upper(): (float(v) if v else None) for k, v in words[1:]}
        if cmd[0] == "T":
            tool = int(float(cmd[1:]))
            continue
        try:
            code = float(cmd[1:])
        except ValueError:
            continue
        if code != int(code):
            continue
        cmd = cmd[0] + str(int(code))
        if cmd == "G20":
            sys.exit(f"{path}: inch units")
        if cmd in ("G90", "G91"):
            rel = cmd == "G91"
        elif cmd == "M82":
            m83 = False
        elif cmd == "M83":
            m83 = True
        elif cmd == "M200" and w.get("D") is not None and args["volumetric"] is None:
            vol_e = w["D"] > 0
        elif cmd == "M221" and w.get("S") is not None:
            flow = w["S"] / 100
        elif cmd == "G28":
            axes = [i for i, a in enumerate("XYZ") if a in w] or [0, 1, 2]
            for i in axes:
                pos[i] = off[i] = 0.0
        elif cmd == "G92":
            if not w:
                w = {"X": 0.0, "Y": 0.0, "Z": 0.0, "E": 0.0}
            for i, a in enumerate("XYZ"):
                if a in w:
                    off[i] += pos[i] - w[a]
                    pos[i] = w[a]
            if "E" in w:
                e = w["E"]
        elif cmd in ("G0", "G1", "G2", "G3"):
            p0 = [pos[i] + off[i] for i in range(3)]
            for i, a in enumerate("XYZ"):
                if a in w:
                    pos[i] = pos[i] + w[a] if rel else w[a]
            p1 = [pos[i] + off[i] for i in range(3)]
            de = 0.0
            if "E" in w:
                de = w["E"] if (rel or m83) else w["E"] - e
                e = e + w["E"] if (rel or m83) else w["E"]
            if de == 0:
                continue
            de *= flow
            if vol_e:
                dv = de
            else:
                d = per_tool(cfg["diam"], tool, args["diameter"], args["override"])
                if not d:
                    sys.exit(f"{path}: no filament diameter (give --diameter)")
                dv = math.pi * d * d / 4 * de
            if dv < 0:
                owed[tool] = owed.get(tool, 0.0) - dv
                continue
            pay = min(dv, owed.get(tool, 0.0))
            owed[tool] = owed.get(tool, 0.0) - pay
            dv -= pay
            if dv <= 0:
                continue
            z = p1[2]
            if height > 0:
                h = height
            else:
                i = bisect.bisect_left(levels, z - 1e-4)
                h = z - (levels[i - 1] if i > 0 else 0.0)
                h = h if h > 1e-4 else 0.0
            counts = feature != CUSTOM and not (feature == UNLABELLED and cfg["labelled"])
            if counts:
                i = bisect.bisect_left(levels, z - 1e-4)
                if not (i < len(levels) and abs(levels[i] - z) <= 1e-4):
                    levels.insert(i, z)
            r_kg_mm3 = 1e-6 * per_tool(cfg["dens"], tool, args["density"], args["override"])
            centre = None
            if cmd in ("G2", "G3"):
                if "I" in w or "J" in w:
                    centre = (p0[0] + (w.get("I") or 0.0), p0[1] + (w.get("J") or 0.0))
                else:
                    r = w["R"]
                    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
                    dd = math.hypot(dx, dy)
                    hh = math.sqrt(max(r * r - dd * dd / 4, 0.0))
                    side = (1 if cmd == "G3" else -1) * (-1 if r < 0 else 1)
                    centre = ((p0[0] + p1[0]) / 2 - side * hh * dy / dd,
                              (p0[1] + p1[1]) / 2 + side * hh * dx / dd)
                centre = (centre, cmd == "G3", w.get("P") or 0)
            segs.append((p0, p1, centre, dv, h, feature, r_kg_mm3))
    return cfg, segs


GL2 = (np.array([-1, 1]) / math.sqrt(3), np.array([1.0, 1.0]))  # on [-1, 1]
GL8 = np.polynomial.legendre.leggauss(8)


def quadrature(segs, line_model):
    """Points (mm) and weights (kg) whose sums give every bead's mass moments, and the
    beads' extents (x, y with w/2, z from the nozzle down by h) and features."""
    pts, wts, feats, ext = [], [], [], []
    for p0, p1, arc, vol, h, f, rho in segs:
        p0, p1 = np.array(p0), np.array(p1)
        if arc is None:
            # along: 2 Gauss points on the segment; t in [0, 1]
            ts, tw = (GL2[0] + 1) / 2, GL2[1] / 2
            path = [(p0 + np.outer(ts, p1 - p0), tw, np.repeat([p1 - p0], len(ts), axis=0))]
            length = np.linalg.norm(p1 - p0)
        else:
            (cx, cy), ccw, turns = arc
            r0, r1 = math.hypot(p0[0] - cx, p0[1] - cy), math.hypot(p1[0] - cx, p1[1] - cy)
            a0, a1 = math.atan2(p0[1] - cy, p0[0] - cx), math.atan2(p1[1] - cy, p1[0] - cx)
            sweep = (a1 - a0) if ccw else (a0 - a1)
            while sweep <= 1e-12:
                sweep += 2 * math.pi
            sweep += 2 * math.pi * math.floor(turns)
            n = max(1, math.ceil(sweep / math.radians(2)))
            x, xw = GL8
            t = ((np.arange(n)[:, None] + (x[None, :] + 1) / 2) / n).ravel()
            tw = np.tile(xw / 2 / n, n)
            sgn = 1 if ccw else -1
            ang = a0 + sgn * sweep * t
            r = r0 + (r1 - r0) * t
            pp = np.stack([cx + r * np.cos(ang), cy + r * np.sin(ang),
                           p0[2] + (p1[2] - p0[2]) * t], axis=1)
            # tangent (for the bead's sideways direction); mass uniform in angle
            tang = np.stack([-sgn * np.sin(ang), sgn * np.cos(ang), np.zeros_like(ang)], axis=1)
            path = [(pp, tw, tang)]
            length = sweep * (r0 + r1) / 2
        w = min(vol / (length * h), 3.0) if (h > 0 and length > 0) else 0.0
        for pp, tw, tang in path:
            nxy = np.linalg.norm(tang[:, :2], axis=1)
            nrm = np.zeros_like(tang)
            ok = nxy > 0
            nrm[ok, 0] = -tang[ok, 1] / nxy[ok]
            nrm[ok, 1] = tang[ok, 0] / nxy[ok]
            if line_model or h <= 0:
                acr, aw, up, uw = [0.0], [1.0], [0.0], [1.0]
                shift = 0.0
            else:
                acr, aw = GL2[0] * w / 2, GL2[1] / 2
                up, uw = GL2[0] * h / 2, GL2[1] / 2
                shift = h / 2
            for a, awi in zip(acr, aw):
                for u, uwi in zip(up, uw):
                    q = pp + a * nrm
                    q = q + np.array([0.0, 0.0, u - shift])
                    pts.append(q)
                    wts.append(vol * rho * tw * awi * uwi)
                    feats.append(np.full(len(tw), f))
        xs = [p0[0], p1[0]]
        ys = [p0[1], p1[1]]
        if arc is not None:
            xs += list(pp[:, 0])
            ys += list(pp[:, 1])
        ext.append((min(xs) - w / 2, max(xs) + w / 2, min(ys) - w / 2, max(ys) + w / 2,
                    min(p0[2], p1[2]) - h, max(p0[2], p1[2]), f))
    if not pts:
        return np.zeros((0, 3)), np.zeros(0), np.zeros(0, int), []
    return np.concatenate(pts), np.concatenate(wts), np.concatenate(feats), ext


def main(argv):
    args = {"diameter": None, "density": None, "override": False, "volumetric": None,
            "line": False, "json": False}
    path = None
    it = iter(argv)
    for a in it:
        if a in ("--diameter", "--density"):
            args[a[2:]] = float(next(it))
        elif a == "--volumetric":
            args["volumetric"] = bool(int(next(it)))
        elif a in ("--override", "--line", "--json"):
            args[a[2:]] = True
        elif a.startswith("-"):
            sys.exit(__doc__)
        else:
            path = a
    if not path:
        sys.exit(__doc__)
    cfg, segs = read(path, args)
    unlab_body = not cfg["labelled"]
    body_f = set(range(8)) | ({UNLABELLED} if unlab_body else set())
    vols = [0.0] * 14
    for s in segs:
        vols[s[5]] += s[3]
    pts, wts, feats, ext = quadrature(segs, args["line"])
    sel = np.isin(feats, list(body_f))
    p, m = pts[sel], wts[sel]
    M = m.sum()
    if not M > 0:
        sys.exit(f"{path}: no extrusion in the body")
    com = (m[:, None] * p).sum(0) / M
    d = p - com
    Q = (m[:, None, None] * d[:, :, None] * d[:, None, :]).sum(0)  # kg mm^2
    inertia = np.trace(Q) * np.eye(3) - Q
    bx = [e for e in ext if e[6] in body_f]
    lo = [min(e[0] for e in bx), min(e[2] for e in bx), min(e[4] for e in bx)]
    hi = [max(e[1] for e in bx), max(e[3] for e in bx), max(e[5] for e in bx)]
    axis = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2]
    off = [com[0] - axis[0], com[1] - axis[1]]
    A = (inertia[0, 0] + inertia[1, 1]) / 2
    C = inertia[2, 2] + M * (off[0] ** 2 + off[1] ** 2)
    out = {
        "mass_kg": M,
        "volume_mm3": sum(vols[f] for f in body_f),
        "excluded_volume_mm3": sum(vols[f] for f in range(14) if f not in body_f),
        "com_m": [1e-3 * c for c in com],
        "inertia_kg_m2": [1e-6 * inertia[0, 0], 1e-6 * inertia[1, 1], 1e-6 * inertia[2, 2],
                          1e-6 * inertia[0, 1], 1e-6 * inertia[0, 2], 1e-6 * inertia[1, 2]],
        "bbox_min_m": [1e-3 * v for v in lo],
        "bbox_max_m": [1e-3 * v for v in hi],
        "part": {"axis_m": [1e-3 * a for a in axis], "bottom_z_m": 1e-3 * lo[2],
                 "z_cm_m": 1e-3 * (com[2] - lo[2]), "com_offset_m": [1e-3 * o for o in off],
                 "A_kg_m2": 1e-6 * A, "C_kg_m2": 1e-6 * C},
        "feature_volume_mm3": {NAMES[f]: vols[f] for f in range(14) if vols[f] > 0},
    }
    if args["json"]:
        print(json.dumps(out, indent=1))
        return
    print(f"{path}: body {1e3 * M:.6g} g, {out['volume_mm3']:.6g} mm^3 "
          f"({out['excluded_volume_mm3']:.6g} mm^3 excluded)")
    print("centre of mass: x %.4f  y %.4f  z %.4f mm (bed)" % tuple(com))
    print("inertia about it (kg m^2): Ixx %.6e Iyy %.6e Izz %.6e Ixy %.3e Ixz %.3e Iyz %.3e"
          % tuple(out["inertia_kg_m2"]))
    pt = out["part"]
    print("part: axis x %.3f y %.3f mm, bottom z %.3f mm; z_cm %.4f mm, com off axis "
          "(%.4f, %.4f) mm; A %.6e, C %.6e kg m^2"
          % (axis[0], axis[1], lo[2], 1e3 * pt["z_cm_m"], off[0], off[1], pt["A_kg_m2"],
             pt["C_kg_m2"]))
    for k, v in out["feature_volume_mm3"].items():
        print(f"  {k:20s} {v:12.4f} mm^3")


if __name__ == "__main__":
    main(sys.argv[1:])
