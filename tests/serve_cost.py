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

from serve_lib import Server, REPO, check, finish

tippe = sys.argv[1]


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


def timed(srv, path, body, **kw):
    t = time.time()
    st, _, o = srv.post(path, body, **kw)
    return st, time.time() - t, o


SWEEP = {"design": "m12-setscrew-printed"}
# the longest request of the shared lane: a patch-law check of the printed M12 with its
# radius sensitivity (6 s of one core here)
LONG = {"design": "m12-setscrew-printed", "z2_mm": 10, "friction": "patch", "spin_rev_s": 20}

# The scheduling facts below are asserted by order and by the server's own CPU time,
# not by wall-clock bounds: under a loaded machine (the suite runs two tests at a time)
# every request slows alike, but a sweep queued behind a build still answers after it,
# and a job that goes on computing still spends the server's CPU.

# ---- three builds and a film at once: they run on their own lane, one at a time,
# and never hold the workers that answer the sweeps (issue 36: a 0.13 s eval waited 30 s).
# The budget is raised so that a loaded machine cannot turn the queued jobs into 503s:
# the lanes are under test here, the budget below.
with Server(tippe, "--budget", "600") as srv:
    jobs = [("/api/build", {"design": d}) for d in
            ("m12-setscrew-printed", "shell-rod-nylon-printed", "shell-band-printed")]
    jobs.append(("/api/animate", {"design": "m12-setscrew", "z2_mm": 10, "spin_rev_s": 20}))
    done = []  # (status, time answered)
    threads = [threading.Thread(target=lambda p=p, b=b: done.append(
        (srv.post(p, b, raw=True, timeout=300)[0], time.time()))) for p, b in jobs]
    for t in threads:
        t.start()
    time.sleep(0.5)
    during = [srv.post("/api/sweep", SWEEP)[0] for _ in range(5)]
    t_sweeps = time.time()
    for t in threads:
        t.join()
    # the jobs take their lane one at a time (seconds of CPU each): five sweeps held
    # behind them would answer after the last of them
    last_job = max(x[1] for x in done)
    check(during == [200] * 5 and t_sweeps < last_job,
          "during three builds and a film five sweeps answer before the jobs end "
          "(%.2f s before the last)" % (last_job - t_sweeps))
    check(sorted(x[0] for x in done) == [200] * 4,
          "the builds and the film are made (%s)" % sorted(x[0] for x in done))

# ---- the advice (the whole sheet, 1.4 s of CPU here) has a lane of its own: it never
# holds the one worker that answers the sweeps, so a sweep asked while it computes
# answers first
with Server(tippe, "--workers", "1") as srv:
    design = json.load(open(os.path.join(REPO, "designs", "shell-rod-nylon-printed.json")))
    design["notes"] = "a new text: nothing kept"
    order = []
    th = threading.Thread(target=lambda: (srv.post("/api/advice", {"design": design}),
                                          order.append("advice")))
    th.start()
    time.sleep(0.2)
    st2, _, _ = srv.post("/api/sweep", SWEEP)
    order.append("sweep")
    th.join()
    check(st2 == 200 and order == ["sweep", "advice"],
          "an advice being computed: the one worker answers a sweep first (%s)" % order)

# ---- a request past its budget frees its worker at once, not when its work would end:
# the server's CPU from the 503 to the next sweep's answer is the sweep's, not the
# rest of a 6 s check (a check that went on would add seconds)
with Server(tippe, "--workers", "1", "--budget", "1") as srv:
    st, t_long, _ = timed(srv, "/api/check", LONG)
    c0 = cpu_s(srv.proc.pid)
    st2, _, _ = srv.post("/api/sweep", SWEEP)
    spent = cpu_s(srv.proc.pid) - c0
    check(st == 503 and st2 == 200 and spent < 1.0,
          "a 6 s check over a 1 s budget: 503 at %.2f s, and the one worker answers a sweep "
          "for %.2f s of the server's CPU (cancelled, not finished; at most 1 s)" % (t_long, spent))

# ---- so does a request whose client has gone (a page that moved on to a newer edit)
with Server(tippe, "--workers", "1") as srv:
    import socket
    body = json.dumps(LONG).encode()
    c = socket.create_connection((srv.host, srv.port))
    c0 = cpu_s(srv.proc.pid)
    c.sendall(("POST /api/check HTTP/1.1\r\nHost: %s:%d\r\nContent-Type: application/json\r\n"
               "Content-Length: %d\r\n\r\n" % (srv.host, srv.port, len(body))).encode() + body)
    time.sleep(0.5)
    c.close()
    st2, _, _ = srv.post("/api/sweep", SWEEP)
    spent = cpu_s(srv.proc.pid) - c0
    # the check is noticed gone within a second of the worker's CPU (issue 36), so the
    # whole exchange costs under 2 s of CPU where the finished check costs 6
    check(st2 == 200 and spent < 2.0,
          "a 6 s check whose client left after 0.5 s, then a sweep: %.2f s of the server's "
          "CPU in all (cancelled; the whole check is ~6 s)" % spent)

finish()
