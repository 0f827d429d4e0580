#!/usr/bin/env python3
"""The lanes' budgets (docs/serve.md, "Limits"): the advice and the exclusive lane (the
build sheet and its advice, builds, films: one at a time at nice 10, each a whole tippe
build's work) have their own wall-clock budget, --slow-budget (4 x --budget by default),
so that a design whose advice takes longer than the shared lane's budget is answered;
and it is still a limit: past it the advice gets 503 "over budget", as a shared request
past --budget does.

Usage: serve_budget.py TIPPE. Prints 'N passed, M failed'."""
import sys
import time

from serve_lib import Server, check, finish

tippe = sys.argv[1]


ADVICE = {"design": "m12-setscrew-printed"}
# the longest request of the shared lane (tests/serve_cost.py): a patch-law check of the
# printed M12 with its radius sensitivity, seconds of one core, far over 0.3 s
LONG = {"design": "m12-setscrew-printed", "z2_mm": 10, "friction": "patch", "spin_rev_s": 20}

# the shared lane's budget shorter than the advice takes, the slow lanes' generous
with Server(tippe, "--budget", "0.3", "--slow-budget", "600") as srv:
    t = time.time()
    st, _, o = srv.post("/api/advice", ADVICE, timeout=900)
    took = time.time() - t
    check(st == 200, "the advice over 0.3 s (%.1f s) answered within --slow-budget: HTTP %d %s"
          % (took, st, "" if st == 200 else o))
    check(took > 0.3, "the advice took longer than --budget (%.2f s > 0.3 s): the test tests "
          "the slow lane's own budget" % took)
    st, _, o = srv.post("/api/check", LONG, timeout=900)
    check(st == 503 and "over budget" in str(o) and "0.3 s" in str(o),
          "a shared request past --budget still gets 503: HTTP %d %s" % (st, str(o)[:160]))
    log = open(srv.log).read()
    check("0.3 s per request (600 s for the advice, builds and films)" in log,
          "the server says both budgets at start")

# and the slow lanes' budget is a limit too
with Server(tippe, "--budget", "30", "--slow-budget", "0.2") as srv:
    st, _, o = srv.post("/api/advice", {"design": "drilled-ball-blind-printed"}, timeout=900)
    check(st == 503 and "over budget: /api/advice took more than 0.2 s" in str(o),
          "an advice past --slow-budget gets 503: HTTP %d %s" % (st, str(o)[:160]))

# by default the slow lanes get 4 x --budget
with Server(tippe, "--budget", "2") as srv:
    log = open(srv.log).read()
    check("2 s per request (8 s for the advice, builds and films)" in log,
          "--slow-budget defaults to 4 x --budget: %s" % log.strip().splitlines()[-1][:200])
finish()
