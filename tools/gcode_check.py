#!/usr/bin/env python3
"""The mass moments of a printed body, summed from the G-code a slicer wrote for it.

Independent of tippe's print model: it reads only the G-code (PrusaSlicer's ;TYPE:, ;HEIGHT:
and ;WIDTH: comments, its config block at the end for filament_diameter and
extrusion_multiplier) and numbers given on the command line.

Each printing move (G0/G1 with X/Y motion and dE > 0) deposits the filament volume
pi d^2 / 4 x dE x extrusion_multiplier, spread uniformly along the segment, at the height
z - h / 2 (the nozzle is at the top of the bead, h from ;HEIGHT:). Moves whose ;TYPE: is
Skirt/Brim, Support material, Support material interface, Wipe tower or Custom are not body:
they are summed apart. G90/G91, M82/M83 and G92 are followed; retractions (E without XY
motion) deposit nothing; G2/G3 arcs and volumetric E (M200) are refused.

Moments: a segment's uniform line mass gives the exact first and second moments along the
segment ((a^2 + a b + b^2) / 3), plus the bead's own cross-section (h^2 / 12 vertically,
w^2 / 12 across the segment). The body's axis is the vertical line through the centre of the
xy bounding box of its extrusions (or --axis-xy), and its design z is gcode z + --z-bottom-mm
(the design height of the plane the body stands on; `tippe export --json` gives the body's
bounding box). C is about the axis, A about a horizontal axis through the centre of mass
(the mean of the x and y ones; both are printed).

    tools/gcode_check.py OUT.gcode --density 1.08 --z-bottom-mm -24.339 [--json] [--layers CSV]
"""
import argparse
import json
import math
import re
import sys

import numpy as np

NOT_BODY = ("Skirt/Brim", "Support material", "Support material interface", "Wipe tower",
            "Custom")
WORD = re.compile(r"([A-Z])([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)")


def config_block(lines):
    cfg = {}
    for line in lines:
        if line.startswith("; ") and " = " in line:
            k, v = line[2:].split(" = ", 1)
            cfg[k.strip()] = v.strip()
    return cfg


def parse(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    cfg = config_block(lines[-800:] if len(lines) > 800 else lines)
    d = float(cfg.get("filament_diameter", "1.75").split(",")[0])
    mult = float(cfg.get("extrusion_multiplier", "1").split(",")[0])
    if cfg.get("use_volumetric_e", "0") == "1":
        raise SystemExit(f"{path}: volumetric E (use_volumetric_e = 1) is not supported")
    area = math.pi * d * d / 4 * mult
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0, "E": 0.0}
    abs_xyz, abs_e = True, True
    typ, h, w, obj = "None", 0.2, 0.45, ""
    segs = []  # x0 y0 x1 y1 z h w volume type-index object-index
    types, objects = [], []
    tix, oix = {}, {}
    for line in lines:
        if line.startswith(";"):
            if line.startswith(";TYPE:"):
                typ = line[6:].strip()
            elif line.startswith(";HEIGHT:"):
                h = float(line[8:])
            elif line.startswith(";WIDTH:"):
                w = float(line[7:])
            elif line.startswith("; printing object "):
                obj = line[len("; printing object "):].strip()
            elif line.startswith("; stop printing object"):
                obj = ""
            continue
        code = line.split(";", 1)[0].strip().upper()
        if not code:
            continue
        cmd = code.split()[0]
        if cmd in ("G2", "G3"):
            raise SystemExit(f"{path}: arc moves (G2/G3) are not supported")
        if cmd == "M200" and "D0" not in code.replace(" ", ""):
            raise SystemExit(f"{path}: M200 volumetric extrusion is not supported")
        if cmd == "G90":
            abs_xyz, abs_e = True, True
        elif cmd == "G91":
            abs_xyz, abs_e = False, False
        elif cmd == "M82":
            abs_e = True
        elif cmd == "M83":
            abs_e = False
        elif cmd == "G92":
            for k, v in WORD.findall(code[3:]):
                if k in pos:
                    pos[k] = float(v)
        elif cmd in ("G0", "G1"):
            new = dict(pos)
            for k, v in WORD.findall(code[len(cmd):]):
                if k in ("X", "Y", "Z"):
                    new[k] = float(v) if abs_xyz else pos[k] + float(v)
                elif k == "E":
                    new[k] = float(v) if abs_e else pos[k] + float(v)
            de = new["E"] - pos["E"]
            moved = new["X"] != pos["X"] or new["Y"] != pos["Y"]
            if de > 0 and moved:
                if typ not in tix:
                    tix[typ] = len(types)
                    types.append(typ)
                if obj not in oix:
                    oix[obj] = len(objects)
                    objects.append(obj)
                segs.append((pos["X"], pos["Y"], new["X"], new["Y"], new["Z"], h, w,
                             area * de, tix[typ], oix[obj]))
            pos = new
    a = np.array(segs, dtype=float).reshape(-1, 10)
    return a, types, objects, cfg


def moments(a, axis_xy, z_bottom):
    """Volume, centroid and second moments (about the given axis and the centroid's height)."""
    x0, y0, x1, y1 = a[:, 0] - axis_xy[0], a[:, 1] - axis_xy[1], a[:, 2] - axis_xy[0], a[:, 3] - axis_xy[1]
    z = a[:, 4] - a[:, 5] / 2 + z_bottom
    h, w, v = a[:, 5], a[:, 6], a[:, 7]
    V = v.sum()
    if V <= 0:
        return None
    mx = (v * (x0 + x1) / 2).sum() / V
    my = (v * (y0 + y1) / 2).sum() / V
    mz = (v * z).sum() / V
    L2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
    L2 = np.where(L2 > 0, L2, 1.0)
    # bead cross-section: w^2/12 across the segment, split into x and y by its direction
    ax2 = (y1 - y0) ** 2 / L2 * w * w / 12
    ay2 = (x1 - x0) ** 2 / L2 * w * w / 12
    sxx = (v * ((x0 * x0 + x0 * x1 + x1 * x1) / 3 + ax2)).sum()
    syy = (v * ((y0 * y0 + y0 * y1 + y1 * y1) / 3 + ay2)).sum()
    szz = (v * ((z - mz) ** 2 + h * h / 12)).sum()
    return {"volume_mm3": V, "centroid_mm": [mx, my, mz],
            "Sxx": sxx, "Syy": syy, "Szz": szz}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("gcode")
    ap.add_argument("--density", type=float, required=True, help="g/cm^3 of the body's material")
    ap.add_argument("--z-bottom-mm", type=float, default=0.0,
                    help="design z of the bed plane (the body's lowest point)")
    ap.add_argument("--axis-xy", type=float, nargs=2, default=None,
                    help="bed x, y of the body's axis (default: centre of its xy bounding box)")
    ap.add_argument("--object", default=None, help="only the object whose name starts with this")
    ap.add_argument("--layers", default=None, help="write per-layer volumes by type to this CSV")
    ap.add_argument("--json", action="store_true")
    o = ap.parse_args()
    a, types, objects, cfg = parse(o.gcode)
    if o.object is not None:
        keep = [i for i, n in enumerate(objects) if n.startswith(o.object)]
        a = a[np.isin(a[:, 9], keep)]
    body_t = [i for i, t in enumerate(types) if t not in NOT_BODY]
    body = a[np.isin(a[:, 8], body_t)]
    if o.axis_xy is None:
        xs = np.concatenate([body[:, 0], body[:, 2]])
        ys = np.concatenate([body[:, 1], body[:, 3]])
        axis = ((xs.min() + xs.max()) / 2, (ys.min() + ys.max()) / 2)
    else:
        axis = tuple(o.axis_xy)
    m = moments(body, axis, o.z_bottom_mm)
    rho = o.density / 1000.0  # g/mm^3
    by_type = {}
    for i, t in enumerate(types):
        sel = a[a[:, 8] == i]
        by_type[t] = {"volume_mm3": float(sel[:, 7].sum()), "body": t not in NOT_BODY,
                      "mass_g": float(sel[:, 7].sum() * rho)}
    V = m["volume_mm3"]
    zc = m["centroid_mm"][2]
    Ax = (m["Syy"] + m["Szz"]) * rho  # about the x axis through the centroid: y^2 + z^2
    Ay = (m["Sxx"] + m["Szz"]) * rho
    C = (m["Sxx"] + m["Syy"]) * rho
    out = {"gcode": o.gcode, "density_g_cm3": o.density,
           "filament_diameter_mm": float(cfg.get("filament_diameter", "1.75").split(",")[0]),
           "axis_xy_mm": list(axis), "z_bottom_mm": o.z_bottom_mm,
           "body_volume_mm3": V, "body_mass_g": V * rho,
           "com_xy_offset_mm": m["centroid_mm"][:2], "com_z_mm": zc,
           "A_g_mm2": (Ax + Ay) / 2, "A_x_g_mm2": Ax, "A_y_g_mm2": Ay, "C_g_mm2": C,
           "by_type": by_type,
           "slicer_filament_cm3": cfg.get("filament used [cm3]"),
           "layer_count": int(len(np.unique(np.round(body[:, 4], 4))))}
    if o.layers:
        zs = np.round(a[:, 4], 4)
        with open(o.layers, "w") as f:
            f.write("z_top_mm,design_z_mid_mm," + ",".join(t.replace(",", " ") for t in types) + "\n")
            for z in np.unique(zs):
                sel = a[zs == z]
                hh = sel[0, 5]
                vals = [sel[sel[:, 8] == i][:, 7].sum() for i in range(len(types))]
                f.write(f"{z:.4f},{z - hh / 2 + o.z_bottom_mm:.4f}," +
                        ",".join(f"{v:.6f}" for v in vals) + "\n")
    if o.json:
        json.dump(out, sys.stdout, indent=1)
        print()
    else:
        print(f"{o.gcode}: body {V:.1f} mm^3 = {V * rho:.3f} g at {o.density} g/cm^3")
        print(f"  centre of mass z {zc:.3f} mm (design), off axis by "
              f"{math.hypot(*m['centroid_mm'][:2]):.3f} mm")
        print(f"  A {out['A_g_mm2']:.1f} g mm^2 (x {Ax:.1f}, y {Ay:.1f}), C {C:.1f} g mm^2")
        for t, b in by_type.items():
            print(f"  {t:28s} {b['volume_mm3']:10.1f} mm^3 {b['mass_g']:8.3f} g"
                  f"{'' if b['body'] else '  (not body)'}")


if __name__ == "__main__":
    main()
