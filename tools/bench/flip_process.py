#!/usr/bin/python3
"""Whole-process cost of one `tippe simulate` of the Figure 12 flip at rtol 1e-9,
beside SciPy's DOP853 on the same equations (reference_scipy.py's right-hand side)
over the same model time, at the same rtol and per-component atol.

    /usr/bin/python3 tools/bench/flip_process.py TIPPE [BASE_TIPPE] [REPEATS]

TIPPE (and BASE_TIPPE, an older build, if given) run interleaved, REPEATS times
(default 7); the median wall time of each whole process is printed, with the
model time it integrated (tippe stops at its proved verdict). Times are CPU times
(user + sys: getrusage of the child for tippe's whole process, process_time around
solve_ivp for SciPy), medians; SciPy integrates from 0 to the same end time, median
of 3. On a shared machine read the ratios of interleaved runs.
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


def run_tippe(exe):
    """CPU time (user + sys) of the whole child process: less sensitive than wall
    time to the other jobs of a shared machine."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([exe, "simulate", SCENARIO, "--rtol", "1e-9", "--json"],
                         check=True, capture_output=True, text=True).stdout
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return cpu, json.loads(out)


def main():
    exe = sys.argv[1]
    base = sys.argv[2] if len(sys.argv) > 2 and sys.argv[2] != "-" else None
    reps = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    walls = {exe: [], base: []}
    last = {}
    for _ in range(reps):
        for e in ([exe, base] if base else [exe]):
            w, d = run_tippe(e)
            walls[e].append(w)
            last[e] = d
    d = last[exe]
    T = d["last"]["t_s"] if "last" in d else d["t_s"]
    print(f"tippe {exe}: median {1e3 * statistics.median(walls[exe]):.2f} ms CPU, whole process, "
          f"verdict {d['verdict']} at t = {d['t_s']:.6g} s, {d['rhs_evals']} RHS evaluations")
    if base:
        db = last[base]
        print(f"base  {base}: median {1e3 * statistics.median(walls[base]):.2f} ms CPU, whole process, "
              f"verdict {db['verdict']} at t = {db['t_s']:.6g} s, {db['rhs_evals']} RHS evaluations")
        print(f"base / new: {statistics.median(walls[base]) / statistics.median(walls[exe]):.2f}")
    m, R, eps, A, C, g, mu = 1.0, 1.0, 0.3, 0.92, 1.0, 1.0, 0.04
    theta0, spin = 0.01, 3.0
    c = math.cos(theta0)
    phi_dot = (C * spin + math.sqrt(C * C * spin * spin + 4 * A * m * g * eps * c)) / (2 * A * c)
    y0 = initial_state(theta0, 0.0, phi_dot, spin, 0.0, 0.0)
    W = math.sqrt(sum(x * x for x in y0[3:6])) + math.sqrt(g / R)
    E0 = energy(y0, m, R, eps, A, C, g)
    scale = np.array([1, 1, 1, W, W, W, R * W, R * W, E0])
    T = d["t_s"]
    times = []
    for _ in range(3):
        cnt = [0]
        rhs = make_rhs(m, R, eps, A, C, g, mu, cnt)
        t0 = time.process_time()
        sol = solve_ivp(rhs, (0.0, T), y0, method="DOP853", rtol=1e-9, atol=1e-9 * scale)
        times.append(time.process_time() - t0)
    th, n = theta_spin(sol.y[:, -1])
    print(f"scipy DOP853 0..{T:.6g} s: median {1e3 * statistics.median(times):.1f} ms "
          f"CPU (solve_ivp only), {cnt[0]} RHS evaluations, theta(T) = {th:.6f} "
          f"(tippe at its decision: {d['theta_rad']:.6f})")
    print(f"scipy / tippe (whole process): "
          f"{statistics.median(times) / statistics.median(walls[exe]):.1f}")


if __name__ == "__main__":
    main()
