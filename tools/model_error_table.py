#!/usr/bin/env python3
"""docs/printing.md's table of the print model's error term ("Tolerances of a sliced
part"): tippe build's verdict and robust stays up / flips / hangs (mm) of every
shipped printed design at 15, 25 and 50 % infill, the part as made, without the
print.model_error tolerance and with it (the default). Prints the table's rows;
--check NAME:INFILL ... compares those rows with docs/printing.md's instead
(exit 1 naming each row that differs). Usage, from the repository root after the
quick start: tools/model_error_table.py [--check drilled-ball-blind-printed:50 ...]"""
import json
import os
import re
import subprocess
import sys
import tempfile

TIPPE = os.environ.get("TIPPE", "build/tippe")
DESIGNS = ["drilled-ball-blind-printed", "m12-setscrew-printed", "m3-setscrew-printed",
           "shell-band-printed", "shell-rod-iron-printed", "shell-rod-nylon-printed",
           "shell-rod-through-printed"]
INFILLS = [15, 25, 50]


def verdict(name, infill, with_term, out_dir):
    d = json.load(open("designs/%s.json" % name))
    part = [p["name"] for p in d["parts"] if p.get("print")][0]  # one printed body each
    cmd = [TIPPE, "build", "designs/%s.json" % name, "-o", out_dir, "--no-export", "--json",
           "--set", "parts.%s.print.infill=%g" % (part, infill / 100)]
    if not with_term:  # the block replaced: the other defaults stay (design-format.md)
        cmd += ["--set", 'tolerances={"parts.%s.print.model_error": 0}' % part]
    b = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    widths = ["%.2f" % s["robust_width_mm"] if s.get("robust") else "-" for s in b["settings"]]
    return "%s (%s)" % (b["verdict"], "/".join(widths))


def row(name, infill, out_dir):
    return "| %s | %d %% | %s | %s |" % (name, infill, verdict(name, infill, False, out_dir),
                                         verdict(name, infill, True, out_dir))


def main(argv):
    with tempfile.TemporaryDirectory() as tmp:
        if argv[:1] == ["--check"]:
            doc = open("docs/printing.md").read()
            bad = 0
            for spec in argv[1:]:
                name, infill = spec.split(":")
                want = row(name, int(infill), tmp)
                m = re.search(r"^\| %s \| %s %% \| [^|]+ \| [^|]+ \|$" % (re.escape(name), infill),
                              doc, re.M)
                if not m or m.group(0) != want:
                    print("docs/printing.md: %s\n  the program: %s" %
                          (m.group(0) if m else "no row for %s" % spec, want))
                    bad = 1
            return bad
        print("| design | infill | without | with (default) |\n|---|---|---|---|")
        for name in DESIGNS:
            for infill in INFILLS:
                print(row(name, infill, tmp), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
