#!/usr/bin/env python3
"""The print model against PrusaSlicer's G-code under three print profiles, for docs/printing.md.

For every shipped printed design with one printed body, at 15, 25 and 40 % infill, runs
`tippe slice --profile P` (PrusaSlicer headless; the 3MF carries tippe's per-object settings,
those of tippe_print_assumed_settings included) with
  - shipped:  designs/slicer/prusa-pla-0.4mm.ini;
  - defaults: PrusaSlicer's own defaults (`prusa-slicer --save`, nothing loaded: among others
              solid_infill_below_area 70, extra_perimeters and thin_walls on, a 0.35 mm first
              layer of 200 % width, which a 3MF cannot set per object);
  - maker:    the shipped profile with the choices issue 40 met in makers' profiles: thick_bridges
              off, solid_infill_below_area 70, extra_perimeters and thin_walls on, the classic
              perimeter generator, rectilinear top and bottom;
and, with the shipped profile, the design's print block changed in the three settings it models
that a maker may want otherwise (the 3MF carries them, so the slicer follows the design):
  - thin bridges: "thick_bridges": false;
  - area 70:      "solid_infill_below_area_mm2": 70 (2.5's built-in default);
  - classic:      "perimeter_generator": "classic";
and prints a Markdown table of the body's mass and A/C, G-code against model. The model does not
see the profile: where the 3MF pins a setting, every profile slices what it modelled.

Usage: tools/profiles_vs_model.py [BUILD_DIR] [OUT_DIR]  (defaults: build, out/profiles)
About 108 slicings: 15 minutes on two cores.
"""
import glob
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "build")
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "out", "profiles")
tippe = os.path.join(build, "tippe")
os.makedirs(out, exist_ok=True)

shipped = os.path.join(here, "designs", "slicer", "prusa-pla-0.4mm.ini")
defaults = os.path.join(out, "prusa-defaults.ini")
subprocess.run(["prusa-slicer", "--save", defaults], check=True, capture_output=True)
maker = os.path.join(out, "maker.ini")
changes = {"thick_bridges": "0", "solid_infill_below_area": "70", "extra_perimeters": "1",
           "thin_walls": "1", "perimeter_generator": "classic",
           "top_fill_pattern": "rectilinear", "bottom_fill_pattern": "rectilinear"}
with open(shipped) as f, open(maker, "w") as g:
    for line in f:
        key = line.split("=")[0].strip()
        g.write("%s = %s\n" % (key, changes[key]) if key in changes else line)
# (name, profile, print block setting or None)
profiles = [("shipped", shipped, None), ("defaults", defaults, None), ("maker", maker, None),
            ("thin bridges", shipped, "thick_bridges=false"),
            ("area 70", shipped, "solid_infill_below_area_mm2=70"),
            ("classic", shipped, "perimeter_generator=classic")]

print("| design | infill | profile / print block | mass G-code g | model g | mass off "
      "| A/C body G-code | model | A/C off |")
print("|---|---|---|---|---|---|---|---|---|")
for design in sorted(glob.glob(os.path.join(here, "designs", "*-printed.json"))):
    d = json.load(open(design))
    printed = [p for p in d["parts"] if p.get("print")]
    if len(printed) != 1:
        continue
    body = printed[0]["name"]
    name = os.path.basename(design)[:-5]
    for infill in (0.15, 0.25, 0.4):
        for pname, prof, block in profiles:
            dest = os.path.join(out, "%s-%g-%s" % (name, infill, pname.replace(" ", "-")))
            cmd = [tippe, "slice", design, "-o", dest, "--json", "--profile", prof,
                   "--set", "parts.%s.print.infill=%g" % (body, infill)]
            if block:
                cmd += ["--set", "parts.%s.print.%s" % (body, block)]
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode:
                print("| %s | %g %% | %s | slice failed: %s |" %
                      (name, 100 * infill, pname, r.stderr.strip()[-200:]))
                continue
            p = json.loads(r.stdout)["sliced_parts"]["printed_parts"][0]
            g, m = p["printed_mass_kg"] * 1e3, p["model_mass_kg"] * 1e3
            ag, am = p["body_A_over_C"], p["model_body_A_over_C"]
            print("| %s | %g %% | %s | %.2f | %.2f | %+.1f %% | %.4f | %.4f | %+.4f |" %
                  (name, 100 * infill, pname, g, m, 100 * (m / g - 1), ag, am, am - ag))
            sys.stdout.flush()
