#!/usr/bin/env python3
"""What tippe serve's requests cost, measured in the server's own CPU time (from
/proc: what the request computed, whatever else runs on the machine): the verdict
the page asks after every edit costs at most twice the sweep (issue 36: it cost 40
to 80 times, the whole build sheet with its launches and advice); the advice is
kept per design text (asked again, it costs nothing); and long jobs (builds,
films) do not hold the workers that answer sweeps.

Usage: serve_cost.py TIPPE. Prints 'N passed, M failed'."""
import json
import os
import sys
import threading
import time

from serve_lib import Server, REPO

tippe = sys.argv[1]
passed, failed = 0, 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print("ok   " + what)
    else:
        failed += 1
        print("FAIL " + what)


def cpu_s(pid):
    """User and system CPU time of the process so far (clock ticks of 10 ms)."""
    f = open("/proc/%d/stat" % pid).read().rsplit(")", 1)[1].split()
    return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")


PRINTED = ["m12-setscrew-printed", "shell-rod-nylon-printed", "drilled-ball-blind-printed"]

with Server(tippe, "--workers", "1") as srv:
    pid = srv.proc.pid
    cost = {}
    for ep in ("/api/sweep", "/api/verdict"):
        c0 = cpu_s(pid)
        for name in PRINTED:
            design = json.load(open(os.path.join(REPO, "designs", name + ".json")))
            for i in range(4):  # four edits: a new design text each
                design["notes"] = "edit %d of %s" % (i, ep)
                st, _, o = srv.post(ep, {"design": design})
                assert st == 200, o
        cost[ep] = cpu_s(pid) - c0
    # 12 requests of ~20 ms each: ~0.2 s, 20 ticks; 2x leaves room for the ticks' rounding
    check(cost["/api/verdict"] <= 2 * cost["/api/sweep"],
          "the verdict after an edit costs %.3f s of CPU, the sweep %.3f s (12 edits of 3 "
          "printed designs; at most twice)" % (cost["/api/verdict"], cost["/api/sweep"]))

    # the advice: the whole sheet, once per design text
    design = json.load(open(os.path.join(REPO, "designs", "m12-setscrew-printed.json")))
    design["notes"] = "advice"
    c0 = cpu_s(pid)
    st, _, first = srv.post("/api/advice", {"design": design})
    c1 = cpu_s(pid)
    st2, _, again = srv.post("/api/advice", {"design": design})
    c2 = cpu_s(pid)
    check(st == 200 and st2 == 200 and first == again and c1 - c0 > 0.2 and c2 - c1 < 0.05,
          "the advice costs %.2f s once, %.3f s asked again for the same design (kept)" %
          (c1 - c0, c2 - c1))

print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
