#!/usr/bin/env python3
"""An uploaded G-code read with the design's print.filament_diameter_mm (issue 40's Cura
case, on the page): the same G-code as a file (tippe eval --set parts.body.print.gcode=FILE)
and as an upload (/api/eval with "upload:ID") give the same printed body, with the design's
diameter and without it. The G-code is PrusaSlicer's of the printed M12 (tools/slice.sh, E in
mm of 1.75 mm filament); read as if it were 1.75 sqrt(1.02) mm, every bead holds 2 % more.

Usage: serve_gcode_diameter.py TIPPE WORKDIR. Prints 'N passed, M failed'."""
import json
import math
import os
import shutil
import subprocess
import sys

from serve_lib import Server, REPO, check, finish

tippe, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


design_file = os.path.join(REPO, "designs", "m12-setscrew-printed.json")
subprocess.run(["tools/slice.sh", design_file, os.path.join(work, "sl")], cwd=REPO,
               env=dict(os.environ, TIPPE=tippe), capture_output=True, check=True)
gfile = os.path.join(work, "sl", "m12-setscrew-printed.gcode")
gcode = open(gfile, "rb").read()
D = 1.75 * math.sqrt(1.02)  # a diameter that puts 2 % more plastic in every bead


def body(evaluation):
    return [p for p in evaluation["printed_parts"] if p["model"] == "gcode"][0]


def cli(diameter):
    args = [tippe, "eval", design_file, "--z2", "5", "--json",
            "--set", "parts.body.print.gcode=" + gfile]
    if diameter:
        args += ["--set", "parts.body.print.filament_diameter_mm=%.17g" % diameter]
    return json.loads(subprocess.run(args, cwd=REPO, capture_output=True, text=True,
                                     check=True).stdout)


with Server(tippe) as srv:
    st, _, up = srv.post("/api/gcode?name=m12.gcode", gcode,
                         headers={"Content-Type": "text/x-gcode"})
    check(st == 200, "the G-code uploaded: %s" % up.get("gcode", up))
    page = {}
    for diameter in (0, D, 0):  # the file's own again after: the upload itself unchanged
        design = json.load(open(design_file))
        design["parts"][0]["print"] = {"gcode": up["gcode"]}
        if diameter:
            design["parts"][0]["print"]["filament_diameter_mm"] = diameter
        st, _, e = srv.post("/api/eval", {"design": design, "z2_mm": 5})
        check(st == 200, "/api/eval with the upload, diameter %s: HTTP %d %s" %
              (diameter or "the file's", st, "" if st == 200 else e))
        if st != 200:
            continue
        c = cli(diameter)
        # one reader, one body: the page's is the command's to rounding (1e-12)
        pm, cm = body(e)["printed_mass_kg"], body(c)["printed_mass_kg"]
        check(abs(pm - cm) <= 1e-12 * cm and abs(e["A_kg_m2"] - c["A_kg_m2"]) <= 1e-12 * c["A_kg_m2"],
              "diameter %s: the page's body is the command's (%.6f g, %.6f g)" %
              (diameter or "the file's", pm * 1e3, cm * 1e3))
        page[diameter] = pm
    if 0 in page and D in page:
        # every bead's volume is (pi d^2 / 4) dE: 2 % more (1e-9: the sums' rounding)
        check(abs(page[D] / page[0] - 1.02) < 1e-9,
              "the design's diameter scales the upload's beads: %.6f g -> %.6f g" %
              (page[0] * 1e3, page[D] * 1e3))
finish()
