#!/usr/bin/env python3
"""What each request of tippe serve costs (a benchmark, not a test): the server's
own CPU time per request (user + system, from /proc, so what else runs on the
machine does not count) and the wall time, for a solid and a printed design,
each request REPEAT times (default 4) with a new design text each time (an
edit: nothing kept), the advice also asked again for the same text (kept).
One worker, so that requests run one at a time.

Usage: tools/bench/serve_costs.py TIPPE [--repeat N]"""
import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests"))
from serve_lib import Server, REPO  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("tippe")
ap.add_argument("--repeat", type=int, default=4)
a = ap.parse_args()


def cpu_s(pid):
    f = open("/proc/%d/stat" % pid).read().rsplit(")", 1)[1].split()
    return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")


REQUESTS = [
    ("sweep", "/api/sweep", {}),
    ("eval", "/api/eval", {"z2_mm": 8}),
    ("verdict", "/api/verdict", {}),
    ("advice", "/api/advice", {}),
    ("advice, asked again", "/api/advice", {"again": True}),
    ("check (viscous)", "/api/check", {"z2_mm": 10, "spin_rev_s": 20}),
    ("check (patch law, 3 radii)", "/api/check", {"z2_mm": 10, "spin_rev_s": 20,
                                                  "friction": "patch"}),
    ("film (WebM, 6 s, 320 x 240)", "/api/animate", {"z2_mm": 10, "spin_rev_s": 20}),
    ("build (zip)", "/api/build", {}),
]

with Server(os.path.abspath(a.tippe), "--workers", "1") as srv:
    pid = srv.proc.pid
    print("%-30s %22s %22s" % ("request", "m12-setscrew", "m12-setscrew-printed"))
    print("%-30s %22s %22s" % ("", "CPU s / wall s", "CPU s / wall s"))
    for what, path, extra in REQUESTS:
        row = []
        for name in ("m12-setscrew", "m12-setscrew-printed"):
            design = json.load(open(os.path.join(REPO, "designs", name + ".json")))
            again = extra.get("again")
            body = {k: v for k, v in extra.items() if k != "again"}
            cpu = wall = 0.0
            for i in range(a.repeat):
                design["notes"] = "edit %d" % i
                body["design"] = design
                if again:
                    srv.post(path, body, raw=True, timeout=120)
                c0, t0 = cpu_s(pid), time.time()
                st, _, o = srv.post(path, body, raw=True, timeout=120)
                cpu += cpu_s(pid) - c0
                wall += time.time() - t0
                if st != 200:
                    sys.exit("%s %s: %d %s" % (path, name, st, o[:200]))
            row.append("%.3f / %.3f" % (cpu / a.repeat, wall / a.repeat))
        print("%-30s %22s %22s" % (what, row[0], row[1]))
    print("load average %.1f, %.1f, %.1f" % os.getloadavg())
