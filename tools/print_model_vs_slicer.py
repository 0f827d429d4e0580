#!/usr/bin/env python3
"""The print model against PrusaSlicer's G-code, for docs/printing.md.

For every shipped printed design with one printed body, at 15, 40 and 100 % infill, runs
`tippe slice` (PrusaSlicer headless, the shipped profile, the hole at the mass model's size),
and prints a Markdown table: the body's mass and A/C from the G-code and from the print model,
the zone boundaries (changes of family I / II / III along Z2) both ways, and how far each of the
model's boundaries moves when the body's moments change by 0.5 % (print.flow 1.005: every line
0.5 % heavier), the measure of a boundary's sensitivity the issue asks for.

Usage: tools/print_model_vs_slicer.py [BUILD_DIR] [OUT_DIR]  (defaults: build, out/slicer)
"""
import glob
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "build")
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "out", "slicer")
tippe = os.path.join(build, "tippe")
os.makedirs(out, exist_ok=True)


def family(g):
    return "III" if g.startswith("III") else "II" if g.startswith("II") else "I"


def boundaries(sweep):
    z = sweep["zones"]
    return [(z[k]["z2_from_mm"], family(z[k - 1]["group"]) + "/" + family(z[k]["group"]))
            for k in range(1, len(z)) if family(z[k - 1]["group"]) != family(z[k]["group"])]


def sweep(design, sets):
    args = [tippe, "sweep", design, "--json"]
    for s in sets:
        args += ["--set", s]
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


print("| design | infill | mass G-code g | model | A/C body G-code | model | boundaries G-code (Z2 mm) "
      "| model | model moved by a 0.5 % heavier body |")
print("|---|---|---|---|---|---|---|---|---|")
for design in sorted(glob.glob(os.path.join(here, "designs", "*-printed.json"))):
    d = json.load(open(design))
    printed = [p for p in d["parts"] if p.get("print")]
    if len(printed) != 1:
        continue
    body = printed[0]["name"]
    name = os.path.basename(design)[:-5]
    for infill in (0.15, 0.4, 1.0):
        sets = ["parts.%s.print.infill=%g" % (body, infill)]
        dest = os.path.join(out, "%s-%g" % (name, infill))
        r = subprocess.run([tippe, "slice", design, "-o", dest, "--json"] +
                           sum((["--set", s] for s in sets), []),
                           capture_output=True, text=True)
        if r.returncode:
            print("| %s | %g %% | slice failed: %s |" % (name, 100 * infill, r.stderr.strip()[-200:]))
            continue
        o = json.loads(r.stdout)
        p = o["sliced_parts"]["printed_parts"][0]
        heavier = sweep(design, sets + ["parts.%s.print.flow=1.005" % body])
        bm, bg, bh = boundaries(o["model"]), boundaries(o["sliced"]), boundaries(heavier)
        moved = ", ".join("%.2f" % abs(h[0] - m[0]) for m, h in zip(bm, bh) if m[1] == h[1])
        fmt = lambda b: ", ".join("%s %.2f" % (k, z) for z, k in b) or "none"
        print("| %s | %g %% | %.2f | %.2f (%+.1f %%) | %.4f | %.4f (%+.4f) | %s | %s | %s |" % (
            name, 100 * infill, 1e3 * p["printed_mass_kg"], 1e3 * p["model_mass_kg"],
            100 * (p["model_mass_kg"] / p["printed_mass_kg"] - 1), p["body_A_over_C"],
            p["model_body_A_over_C"], p["model_body_A_over_C"] - p["body_A_over_C"],
            fmt(bg), fmt(bm), moved or "-"))
