#!/usr/bin/env python3
"""The zone table of each shipped design solid and printed at 15, 20, 40 and 100 %
infill (docs/printing.md). Runs build/tippe sweep --json on designs/NAME.json and
designs/NAME-printed.json with --set parts.PART.print.infill=F for every printed part.
Usage, from the repository root after the quick start: tools/printing_table.py [NAME ...]"""
import json
import subprocess
import sys

TIPPE = __import__("os").environ.get("TIPPE", "build/tippe")
DESIGNS = ["m12-setscrew", "m3-setscrew", "drilled-ball-blind", "shell-rod-iron",
           "shell-rod-nylon", "shell-rod-through", "shell-band"]
INFILLS = [0.15, 0.20, 0.40, 1.00]


def sweep(path, sets):
    cmd = [TIPPE, "sweep", path, "--json"]
    for s in sets:
        cmd += ["--set", s]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def mass_g(path, sets):
    cmd = [TIPPE, "eval", path, "--json", "--z2", "0"]
    for s in sets:
        cmd += ["--set", s]
    d = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    return d["mass_kg"] * 1e3, d["printed_parts"]


def zones_text(r):
    parts = []
    for z in r["zones"]:
        parts.append("%s %.2f–%.2f" % (z["group"], z["z2_from_mm"], z["z2_to_mm"]))
    return " · ".join(parts)


def row(label, path, sets):
    r = sweep(path, sets)
    m, printed = mass_g(path, sets)
    body = sum(p["printed_mass_kg"] for p in printed) * 1e3 if printed else None
    narrow = r.get("narrowest_zone_mm")
    return "| %s | %s | %.2f | %s | %s | %s |" % (
        label, "%.2f" % body if body is not None else "solid", m, zones_text(r),
        "yes" if r["three_in_one"] else "no",
        "%.2f (%s)" % (narrow, r["narrowest_zone_family"]) if r["three_in_one"] else "0")


def main(names):
    print("| top | printed parts g | top g | zones along the stated travel: group Z2 from–to mm | 3-in-1 | narrowest zone mm (0 unless 3-in-1) |")
    print("|---|---|---|---|---|---|")
    for name in names:
        solid = "designs/%s.json" % name
        printed = "designs/%s-printed.json" % name
        print(row("`%s` solid" % name, solid, []))
        _, pp = mass_g(printed, [])
        for f in INFILLS:
            sets = ["parts.%s.print.infill=%g" % (p["part"], f) for p in pp]
            print(row("printed, %d %% infill" % round(100 * f), printed, sets))


if __name__ == "__main__":
    main(sys.argv[1:] or DESIGNS)
