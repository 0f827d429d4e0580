#!/usr/bin/python3
"""The same model, another tool: tippe's regular lab-frame equations of motion
(docs/dynamics.md, paper eqs 3.6-3.19 with viscous friction eq 3.12) written
again in Python and integrated with SciPy's solve_ivp, on the scenarios and at
the tolerances of tools/bench/work_precision.c.

It reads OUTDIR/scenarios.csv (each scenario's top, launch, sample times and
tippe's reference samples), measures the same error metric
    err = max_j max(|theta_j - theta_ref_j|, |n_j - n_ref_j| / W)
and the wall time of solve_ivp from 0 to T, and appends rows with tool "scipy"
to OUTDIR/scipy.csv in wp.csv's columns.

Tolerances as in tippe: rtol, and atol = rtol * scale per component (1 for the
axis, W for omega, R W for velocities, E0 for the dissipated energy). SciPy has
no step cap; tippe caps the step at 1/8 of the period 2 pi / W for its settling
test, which SciPy does not need: the comparison is at equal achieved error.

    usage: /usr/bin/python3 tools/bench/reference_scipy.py OUTDIR [quick]
Needs Debian's python3-scipy (call /usr/bin/python3 explicitly).
"""
import csv
import math
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

CAP_S = 4.0  # once a run takes longer, tighter tolerances of that method are skipped


def make_rhs(m, R, eps, A, C, g, mu, counter):
    """Right-hand side of the regular form on y = (k, omega, v_h, D)."""
    one_minus_AC = 1.0 - A / C
    CmA_A = (C - A) / A

    def rhs(t, y):
        counter[0] += 1
        kx, ky, kz, wx, wy, wz, vx, vy, _ = y
        kn = math.sqrt(kx * kx + ky * ky + kz * kz)
        k0, k1, k2 = kx / kn, ky / kn, kz / kn  # |k| = 1 enters the physics exactly
        n = wx * k0 + wy * k1 + wz * k2
        # omega x k
        c0, c1, c2 = wy * k2 - wz * k1, wz * k0 - wx * k2, wx * k1 - wy * k0
        # q = eps k - R e3 (eq 3.6); v_z = -eps (omega x k)_z (eq 3.11)
        q0, q1, q2 = eps * k0, eps * k1, eps * k2 - R
        # V_Q = v + omega x q (eq 3.7), horizontal
        VQ0 = vx + (wy * q2 - wz * q1)
        VQ1 = vy + (wz * q0 - wx * q2)
        # torque per unit Rn of f = e3 - mu V_Q (eqs 3.12, 3.13)
        f0, f1 = -mu * VQ0, -mu * VQ1
        t0, t1, t2 = q1 - q2 * f1, q2 * f0 - q0, q0 * f1 - q1 * f0
        tk = t0 * k0 + t1 * k1 + t2 * k2
        a10 = (t0 - one_minus_AC * tk * k0) / A
        a11 = (t1 - one_minus_AC * tk * k1) / A
        a12 = (t2 - one_minus_AC * tk * k2) / A
        a00, a01, a02 = -CmA_A * n * c0, -CmA_A * n * c1, -CmA_A * n * c2
        a1k2 = a10 * k1 - a11 * k0
        a0k2 = a00 * k1 - a01 * k0
        wwk2 = wx * c1 - wy * c0
        den = 1.0 + m * eps * a1k2  # eq 3.19's denominator, any m
        if den <= 0.0:
            raise RuntimeError("contact force undetermined (eq 3.19)")
        Rn = m * (g - eps * (a0k2 + wwk2)) / den
        # dk/dt = omega x k on the stored k, so that the exact flow keeps |k|
        return [wy * kz - wz * ky, wz * kx - wx * kz, wx * ky - wy * kx,
                Rn * a10 + a00, Rn * a11 + a01, Rn * a12 + a02,
                -mu * Rn * VQ0 / m, -mu * Rn * VQ1 / m,
                mu * Rn * (VQ0 * VQ0 + VQ1 * VQ1)]  # eqs 3.14, 4.1

    return rhs


def initial_state(theta, theta_dot, phi_dot, spin, U, V):
    """Launch in the paper's variables (eq 3.4), phi = psi = 0."""
    s = 0.0 if theta == math.pi else math.sin(theta)
    co = math.cos(theta)
    i = (co, 0.0, -s)
    j = (0.0, 1.0, 0.0)
    k = (s, 0.0, co)
    w = [-phi_dot * s * i[a] + theta_dot * j[a] + spin * k[a] for a in range(3)]
    return [k[0], k[1], k[2], w[0], w[1], w[2], U, V, 0.0]


def energy(y, m, R, eps, A, C, g):
    k = np.array(y[0:3]) / np.linalg.norm(y[0:3])
    w = np.array(y[3:6])
    n = w @ k
    L = A * w + (C - A) * n * k
    vz = -eps * np.cross(w, k)[2]
    v = np.array([y[6], y[7], vz])
    return 0.5 * m * v @ v + 0.5 * w @ L + m * g * (R - eps * k[2])


def theta_spin(y):
    k = np.array(y[0:3])
    k = k / np.linalg.norm(k)
    return math.atan2(math.hypot(k[0], k[1]), k[2]), float(np.array(y[3:6]) @ k)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: reference_scipy.py OUTDIR [quick]")
    out = sys.argv[1]
    quick = len(sys.argv) > 2 and sys.argv[2] == "quick"
    methods = ["DOP853", "RK45"] if not quick else ["DOP853"]
    rows = list(csv.DictReader(open(f"{out}/scenarios.csv")))
    with open(f"{out}/scipy.csv", "w", newline="") as fo:
        w = csv.writer(fo)
        w.writerow("tool,scenario,stepper,rtol,status,time_s,rhs_evals,steps,rejected,err,"
                   "err_theta_rad,err_n_rel,jellett_drift,energy_err,verdict,t_verdict_s,"
                   "verdict_ok,verdict_time_s,verdict_rhs_evals".split(","))
        for r in rows:
            p = {x: float(r[x]) for x in r if x != "scenario"}
            m, R, eps, A, C, g, mu = (p[x] for x in ("m", "R", "eps", "A", "C", "g", "mu"))
            y0 = initial_state(p["theta"], p["theta_dot"], p["phi_dot"], p["spin"], p["U"], p["V"])
            W, T = p["W"], p["T"]
            ts = [p[f"t{j}"] for j in range(1, 5)]
            th_ref = [p[f"theta_ref{j}"] for j in range(1, 5)]
            n_ref = [p[f"n_ref{j}"] for j in range(1, 5)]
            E0 = energy(y0, m, R, eps, A, C, g)
            scale = np.array([1, 1, 1, W, W, W, R * W, R * W, E0])
            for meth in methods:
                skip = False
                for e in range(3, 14, 2 if quick else 1):
                    rtol = 10.0 ** -e
                    if skip:
                        w.writerow(["scipy", r["scenario"], meth, f"{rtol:g}", "skipped"] + [""] * 14)
                        continue
                    cnt = [0]
                    rhs = make_rhs(m, R, eps, A, C, g, mu, cnt)
                    times = []
                    reps = 1
                    rep = 0
                    status = "ok"
                    while rep < reps:
                        cnt[0] = 0
                        t0 = time.perf_counter()
                        try:
                            sol = solve_ivp(rhs, (0.0, T), y0, method=meth, t_eval=ts,
                                            rtol=rtol, atol=rtol * scale)
                        except RuntimeError:
                            status = "failed"
                            break
                        times.append(time.perf_counter() - t0)
                        if not sol.success:
                            status = "failed"
                            break
                        if rep == 0 and times[0] < 0.2:
                            reps = 3
                        rep += 1
                    if status != "ok":
                        w.writerow(["scipy", r["scenario"], meth, f"{rtol:g}", status] + [""] * 14)
                        skip = True
                        continue
                    e_th = e_n = 0.0
                    for j in range(4):
                        th, n = theta_spin(sol.y[:, j])
                        e_th = max(e_th, abs(th - th_ref[j]))
                        e_n = max(e_n, abs(n - n_ref[j]) / W)
                    tmed = sorted(times)[len(times) // 2]
                    w.writerow(["scipy", r["scenario"], meth, f"{rtol:g}", "ok", f"{tmed:.4e}",
                                cnt[0], "", "", f"{max(e_th, e_n):.3e}",
                                f"{e_th:.3e}", f"{e_n:.3e}", "", "", "", "", "", "", ""])
                    fo.flush()
                    if tmed > CAP_S:
                        skip = True
                print(f"{r['scenario']}: {meth} done", file=sys.stderr, flush=True)


if __name__ == "__main__":
    main()
