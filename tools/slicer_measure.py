#!/usr/bin/env python3
"""Slices every shipped printed design and compares the G-code's body with tippe's print model.

For each designs/*-printed.json and each infill (15, 40, 100 % by default) it runs
tools/slice.sh (tippe export with --clearance-mm 0, so the sliced body is the mass model's;
PrusaSlicer with designs/slicer/prusa-pla-0.4mm.ini), sums the G-code with tools/gcode_check.py,
and asks `tippe eval --json` for the model's printed body (the other parts' densities set to
1e-12 g/cm^3, so the top's mass, centre of mass, A and C are the printed body's). It also
puts each G-code body into the whole top (the hardware's moments are the model's: top minus
body) and gives A/C at the middle of the travel, model and G-code.

    tools/slicer_measure.py [--out DIR] [--infill 0.15,0.4,1] [--design NAME]... [--pattern P]
                            [--json FILE]

Needs $TIPPE (else build/tippe), prusa-slicer and python3-numpy. Writes the G-code under DIR
(default /tmp/slicer-out) and prints a Markdown table.
"""
import argparse
import glob
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TIPPE = os.environ.get("TIPPE", os.path.join(HERE, "build", "tippe"))
PY = sys.executable


def tippe_eval(design, z2, sets):
    cmd = [TIPPE, "eval", design, "--z2", repr(z2), "--json"]
    for s in sets:
        cmd += ["--set", s]
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def about_centre(m, eps, A, C):
    """mass, z-moment, transverse moment about the sphere's centre, axial moment (g, mm)."""
    return m, -m * eps, A + m * eps * eps, C


def measure(design, infill, out, pattern, support, extra_export):
    stem = os.path.basename(design)[:-5]
    full = tippe_eval(design, 0.0, [])
    printed = [p["part"] for p in full["printed_parts"]]
    sets = [f"parts.{p}.print.infill={infill}" for p in printed]
    tag = f"{stem}-{round(infill * 100)}" + (f"-{pattern}" if pattern else "") + \
        ("-support" if support else "") + ("-split" if "--split" in extra_export else "")
    odir = os.path.join(out, tag)
    cmd = ["nice", "-n", "10", os.path.join(HERE, "tools", "slice.sh"), design, odir]
    for s in sets:
        cmd += ["--set", s]
    if pattern:
        cmd += [f"--slicer-arg=--fill-pattern={pattern}"]
    if support:
        cmd += ["--support"]
    cmd += ["--", "--clearance-mm", "0"] + extra_export
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    wall = None
    for line in open(os.path.join(odir, "slicer.log")):
        if line.startswith("slicer wall time"):
            wall = float(line.split()[3])
    exp = json.load(open(os.path.join(odir, "export.json")))
    bodies = exp["bodies"]
    density = None
    for p in full["parts"]:
        if p["name"] in printed:
            density = p["density_g_cm3"]
    gcode = os.path.join(odir, stem + ".gcode")
    zb = bodies[0]["bbox_min_mm"][2] if len(bodies) == 1 else 0.0
    g = json.loads(subprocess.run(
        [PY, os.path.join(HERE, "tools", "gcode_check.py"), gcode, "--density", repr(density),
         "--z-bottom-mm", repr(zb), "--json", "--layers", os.path.join(odir, "layers.csv")],
        check=True, capture_output=True, text=True).stdout)
    # the model's printed body: every other part weightless
    lo, hi = full["travel_mm"]
    z2 = (lo + hi) / 2
    hw = [p["name"] for p in full["parts"] if not p["printed"] and p["role"] != "void"]
    zero = [f"parts.{n}.density_g_cm3=1e-12" for n in hw]
    body = tippe_eval(design, z2, sets + zero)
    top = tippe_eval(design, z2, sets)
    pp = body["printed_parts"]
    model = {"mass_g": body["mass_kg"] * 1e3, "com_z_mm": -body["eps_m"] * 1e3,
             "A_g_mm2": body["A_kg_m2"] * 1e9, "C_g_mm2": body["C_kg_m2"] * 1e9,
             "walls_skins_g": sum(p["skin_mass_kg"] for p in pp) * 1e3,
             "solid_g": sum(p["solid_mass_kg"] for p in pp) * 1e3}
    model["core_g"] = model["mass_g"] - model["walls_skins_g"]
    # whole top at mid travel: hardware = top - body (about the centre), then + G-code body
    t = about_centre(top["mass_kg"] * 1e3, top["eps_m"] * 1e3, top["A_kg_m2"] * 1e9,
                     top["C_kg_m2"] * 1e9)
    b = about_centre(model["mass_g"], -model["com_z_mm"], model["A_g_mm2"], model["C_g_mm2"])
    h = [t[i] - b[i] for i in range(4)]
    gm, gz = g["body_mass_g"], g["com_z_mm"]
    m = gm + h[0]
    mz = gm * gz + h[1]
    eps = -mz / m
    Ac = g["A_g_mm2"] + gm * gz * gz + h[2]
    C = g["C_g_mm2"] + h[3]
    by = g["by_type"]
    walls = sum(by.get(k, {}).get("mass_g", 0) for k in
                ("External perimeter", "Perimeter", "Overhang perimeter", "Gap fill"))
    solid = sum(by.get(k, {}).get("mass_g", 0) for k in
                ("Solid infill", "Top solid infill", "Bridge infill"))
    sparse = by.get("Internal infill", {}).get("mass_g", 0)
    support_g = sum(by.get(k, {}).get("volume_mm3", 0) for k in
                    ("Support material", "Support material interface")) / 1e3
    return {"design": stem, "infill": infill, "pattern": pattern or "gyroid (profile)",
            "support": support, "export": extra_export, "gcode": gcode, "wall_s": wall,
            "layers": g["layer_count"], "gcode_body": g, "model": model,
            "gcode_walls_g": walls, "gcode_solid_infill_g": solid, "gcode_sparse_g": sparse,
            "support_cm3": support_g,
            "z2_mm": z2, "top_A_over_C_model": top["A_over_C"],
            "top_A_over_C_gcode": (Ac - m * eps * eps) / C,
            "top_eps_over_R_model": top["eps_over_R"], "top_eps_over_R_gcode": eps / (top["R_m"] * 1e3)}


def pct(a, b):
    return 100 * (a - b) / b


def table(rows):
    out = ["| design | infill | G-code g | model g | diff | com z G-code / model mm | A G-code / model g mm^2 | diff | C G-code / model g mm^2 | diff | top A/C at mid Z2 G-code / model | walls / solid infill / sparse G-code g | walls+skins / core model g | slice s |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        g, mo = r["gcode_body"], r["model"]
        out.append(
            f"| {r['design']} | {round(r['infill'] * 100)} % | {g['body_mass_g']:.2f} | {mo['mass_g']:.2f} | "
            f"{pct(g['body_mass_g'], mo['mass_g']):+.1f} % | {g['com_z_mm']:+.3f} / {mo['com_z_mm']:+.3f} | "
            f"{g['A_g_mm2']:.0f} / {mo['A_g_mm2']:.0f} | {pct(g['A_g_mm2'], mo['A_g_mm2']):+.1f} % | "
            f"{g['C_g_mm2']:.0f} / {mo['C_g_mm2']:.0f} | {pct(g['C_g_mm2'], mo['C_g_mm2']):+.1f} % | "
            f"{r['top_A_over_C_gcode']:.4f} / {r['top_A_over_C_model']:.4f} | "
            f"{r['gcode_walls_g']:.2f} / {r['gcode_solid_infill_g']:.2f} / {r['gcode_sparse_g']:.2f} | "
            f"{mo['walls_skins_g']:.2f} / {mo['core_g']:.2f} | {r['wall_s']:.1f} |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="/tmp/slicer-out")
    ap.add_argument("--infill", default="0.15,0.4,1")
    ap.add_argument("--design", action="append", default=None)
    ap.add_argument("--pattern", action="append", default=None)
    ap.add_argument("--support", action="store_true")
    ap.add_argument("--split", action="store_true")
    ap.add_argument("--json", default=None)
    o = ap.parse_args()
    designs = o.design or sorted(glob.glob(os.path.join(HERE, "designs", "*-printed.json")))
    designs = [d if d.endswith(".json") else os.path.join(HERE, "designs", d + ".json") for d in designs]
    rows = []
    for d in designs:
        for f in [float(x) for x in o.infill.split(",")]:
            for p in (o.pattern or [None]):
                r = measure(d, f, o.out, p, o.support, ["--split"] if o.split else [])
                rows.append(r)
                print(f"{r['design']} {f} {r['pattern']}: {r['gcode_body']['body_mass_g']:.3f} g "
                      f"(model {r['model']['mass_g']:.3f} g) {r['wall_s']:.1f} s", file=sys.stderr)
    if o.json:
        with open(o.json, "w") as fh:
            json.dump(rows, fh, indent=1)
    print(table(rows))


if __name__ == "__main__":
    main()
