#!/usr/bin/python3
"""Whole-process cost of `tippe simulate designs/scenarios/fig12-tip.json` against
SciPy's DOP853 on the same equations, at EQUAL ERROR (not only equal rtol).

    /usr/bin/python3 tools/bench/equal_error.py TIPPE [REPEATS]

- Reference: DOP853 at rtol 1e-13 (dense output, 0 .. the latest time needed),
  checked against tippe's rk8pd at rtol 1e-13 at tippe's own decision time: their
  difference bounds how small an error can be resolved.
- tippe: `simulate --rtol R --json` for rk8pd and rkck over a range of rtol; it
  stops at its proved verdict (a slightly different time T_R for each run). Its
  error is that of the state it reports, against the reference at the same T_R:
      err = max(|theta - theta_ref|, |n - n_ref| / W),  W = |omega0| + sqrt(g/R)
  (n relative to W because it passes through 0 in a flip, as in work_precision.c).
  Cost: CPU time (user + sys, getrusage) of the whole process, median of REPEATS
  (default 9) runs interleaved over all tolerances.
- SciPy: solve_ivp DOP853 from 0 to T (tippe's decision time at rtol 1e-9) at rtol
  1e-5 .. 1e-12 (atol = rtol x each component's scale, as tippe); error at T against
  the reference; cost: process_time of solve_ivp alone (Python's start-up and
  imports are not counted, which favours SciPy), median of 3 (1 above 1 s).
- Start-up: the same process to t_end = 1 ms, for the share of the process that
  is not integration, and /bin/true, the cost of any process on this machine.
- Then, for each error level, the cheapest run of each tool that reaches it.

    /usr/bin/python3 tools/bench/equal_error.py --scipy-once RTOL T

solves once with DOP853 at RTOL from 0 to T and exits (RTOL 0: imports only), for
instruction counts under valgrind: the difference of the two is SciPy's share.
"""
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from reference_scipy import energy, initial_state, make_rhs, theta_spin  # noqa: E402

SCENARIO = "designs/scenarios/fig12-tip.json"
# The Figure 12 scenario's top and launch (designs/scenarios/fig12-tip.json).
M, R, EPS, A, C, G, MU = 1.0, 1.0, 0.3, 0.92, 1.0, 1.0, 0.04
THETA0, SPIN0 = 0.01, 3.0
TIPPE_RUNS = [("rk8pd", e) for e in range(5, 13)] + [("rkck", e) for e in range(5, 10)]
SCIPY_RTOL_EXP = range(5, 13)
LEVELS = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]


def tippe_run(exe, stepper, rtol, extra=()):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([exe, "simulate", SCENARIO, "--stepper", stepper, "--rtol", f"{rtol:g}",
                          "--json", *extra], check=True, capture_output=True, text=True).stdout
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), json.loads(out)


def launch_state():
    c = math.cos(THETA0)
    phi_dot = (C * SPIN0 + math.sqrt(C * C * SPIN0 ** 2 + 4 * A * M * G * EPS * c)) / (2 * A * c)
    y0 = initial_state(THETA0, 0.0, phi_dot, SPIN0, 0.0, 0.0)
    W = math.sqrt(sum(x * x for x in y0[3:6])) + math.sqrt(G / R)
    scale = np.array([1, 1, 1, W, W, W, R * W, R * W, energy(y0, M, R, EPS, A, C, G)])
    return y0, W, scale


def scipy_solve(y0, scale, T, rtol, dense=False):
    cnt = [0]
    t0 = time.process_time()
    sol = solve_ivp(make_rhs(M, R, EPS, A, C, G, MU, cnt), (0.0, T), y0, method="DOP853",
                    rtol=rtol, atol=rtol * scale, dense_output=dense)
    return time.process_time() - t0, cnt[0], sol


def err_of(theta, n, y_ref, W):
    th_ref, n_ref = theta_spin(y_ref)
    return max(abs(theta - th_ref), abs(n - n_ref) / W)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if sys.argv[1] == "--scipy-once":
        rtol, T = float(sys.argv[2]), float(sys.argv[3])
        if rtol > 0:
            y0, W, scale = launch_state()
            print(scipy_solve(y0, scale, T, rtol)[1], "RHS evaluations")
        return
    exe = sys.argv[1]
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 9
    y0, W, scale = launch_state()

    cpu = {run: [] for run in TIPPE_RUNS}
    last = {}
    startup = []  # the same process with t_end 1 ms: start-up, reading, theory, output
    empty = []  # a process that does nothing: the operating system's share
    for _ in range(reps):
        startup.append(tippe_run(exe, "rk8pd", 1e-9, ("--t-end", "0.001"))[0])
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(["/bin/true"], check=True)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        empty.append((r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime))
        for st, e in TIPPE_RUNS:
            c, d = tippe_run(exe, st, 10.0 ** -e)
            cpu[(st, e)].append(c)
            last[(st, e)] = d
    _, tight = tippe_run(exe, "rk8pd", 1e-13)
    T9 = last[("rk8pd", 9)]["t_s"]
    t_max = max([d["t_s"] for d in last.values()] + [tight["t_s"], T9])
    ref_cpu, ref_evals, ref = scipy_solve(y0, scale, t_max, 1e-13, dense=True)
    check = err_of(tight["theta_rad"], tight["spin_rad_s"], ref.sol(tight["t_s"]), W)
    print(f"reference: DOP853 rtol 1e-13 to {t_max:.6g} s ({ref_evals} evaluations, "
          f"{ref_cpu:.2f} s); against tippe rk8pd 1e-13 at t = {tight['t_s']:.6g} s: {check:.2e}")

    rows = []  # (tool, label, T, err, cost_s, evals)
    for (st, e), d in last.items():
        err = err_of(d["theta_rad"], d["spin_rad_s"], ref.sol(d["t_s"]), W)
        rows.append(("tippe", f"{st} 1e-{e}", d["t_s"], err, statistics.median(cpu[(st, e)]),
                     d["rhs_evals"]))
    y_ref9 = ref.sol(T9)
    for e in SCIPY_RTOL_EXP:
        times = []
        while len(times) < (3 if not times or times[0] < 1.0 else 1):
            c, n_ev, sol = scipy_solve(y0, scale, T9, 10.0 ** -e)
            times.append(c)
        th, n = theta_spin(sol.y[:, -1])
        rows.append(("scipy", f"DOP853 1e-{e}", T9, err_of(th, n, y_ref9, W),
                     statistics.median(times), n_ev))

    print(f"{'tool':6s} {'run':12s} {'T (s)':>10s} {'error':>9s} {'CPU ms':>9s} {'RHS evals':>10s}")
    for r in rows:
        print(f"{r[0]:6s} {r[1]:12s} {r[2]:10.4f} {r[3]:9.2e} {1e3 * r[4]:9.2f} {r[5]:10d}")
    s0 = statistics.median(startup)
    print(f"\nthe same process to t_end = 1 ms (start-up, input, theory, output): {1e3 * s0:.2f} ms CPU;"
          f" /bin/true: {1e3 * statistics.median(empty):.2f} ms CPU")
    print("\ncheapest run reaching each error (tippe: whole process; SciPy: solve_ivp only)")
    for lvl in LEVELS:
        best = {}
        for tool in ("tippe", "scipy"):
            ok = [r for r in rows if r[0] == tool and r[3] <= lvl]
            best[tool] = min(ok, key=lambda r: r[4]) if ok else None
        if best["tippe"] and best["scipy"]:
            bt, bs = best["tippe"], best["scipy"]
            print(f"err <= {lvl:.0e}: tippe {bt[1]} {1e3 * bt[4]:.2f} ms, SciPy {bs[1]} "
                  f"{1e3 * bs[4]:.0f} ms: {bs[4] / bt[4]:.0f}x "
                  f"(tippe's integration alone, process to 1 ms subtracted: {bs[4] / max(bt[4] - s0, 1e-6):.0f}x)")
        else:
            print(f"err <= {lvl:.0e}: not reached by " +
                  " and ".join(t for t in best if best[t] is None))


if __name__ == "__main__":
    main()
