#!/usr/bin/python3
"""Summary of a work-precision run (tools/bench/run.sh): markdown on stdout.

Reads OUTDIR/wp.csv (tippe), OUTDIR/scipy.csv (SciPy, if present),
OUTDIR/reference.csv and OUTDIR/presets.csv. For each scenario it lists the
cheapest run (wall time of the run to T) reaching each error level, for tippe
and for SciPy, and their ratio: "speed ratio at equal achieved error" is
(SciPy's cheapest time to reach err <= X) / (tippe's cheapest time to reach it).
It also gives each preset's row and counts wrong verdicts.

    usage: /usr/bin/python3 tools/bench/summarize.py OUTDIR
"""
import csv
import os
import sys

LEVELS = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10]


def rows(path):
    if not os.path.exists(path):
        return []
    return list(csv.DictReader(open(path)))


def ok(r):
    return r["status"] == "ok" and r["err"] != "" and r["time_s"] != ""


def cheapest(rs, level, stepper=None):
    best = None
    for r in rs:
        if not ok(r) or float(r["err"]) > level:
            continue
        if stepper and r["stepper"] != stepper:
            continue
        if best is None or float(r["time_s"]) < float(best["time_s"]):
            best = r
    return best


def fmt_run(r):
    if r is None:
        return "not reached"
    return f"{r['stepper']} {float(r['rtol']):.0e}: {1e3 * float(r['time_s']):.3g} ms"


def main():
    out = sys.argv[1]
    wp = rows(f"{out}/wp.csv")
    sp = rows(f"{out}/scipy.csv")
    ref = rows(f"{out}/reference.csv")
    presets = rows(f"{out}/presets.csv")
    scen = [r["scenario"] for r in ref]
    print("## Reference solutions\n")
    print("| scenario | reference | verdict | t_verdict (s) | T (s) | check | mutual error | ref cost |")
    print("|---|---|---|---|---|---|---|---|")
    for r in ref:
        print(f"| {r['scenario']} | {r['ref_stepper']} {float(r['ref_rtol']):.0e} | {r['verdict']} | "
              f"{float(r['t_verdict_s']):.6g} | {float(r['T_s']):.6g} | {r['check_stepper']} "
              f"{float(r['check_rtol']):.0e} | {float(r['mutual_err']):.1e} | "
              f"{int(r['ref_rhs_evals'])} evals, {1e3 * float(r['ref_time_s']):.3g} ms |")
    for s in scen:
        ws = [r for r in wp if r["scenario"] == s]
        ss = [r for r in sp if r["scenario"] == s]
        print(f"\n## {s}\n")
        print("Presets (stepper, rtol): error, time to T, RHS evaluations, Jellett drift, verdict run.\n")
        print("| preset | stepper rtol | error | time (ms) | RHS evals | steps | J drift | verdict | right | verdict time (ms) |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for p in presets:
            m = [r for r in ws if r["stepper"] == p["stepper"] and
                 abs(float(r["rtol"]) / float(p["rtol"]) - 1) < 1e-9]
            if not m or not ok(m[0]):
                print(f"| {p['preset']} | {p['stepper']} {float(p['rtol']):.0e} | not measured "
                      f"({m[0]['status'] if m else 'not on the grid'}) | | | | | | | |")
                continue
            r = m[0]
            print(f"| {p['preset']} | {r['stepper']} {float(r['rtol']):.0e} | {float(r['err']):.1e} | "
                  f"{1e3 * float(r['time_s']):.3g} | {r['rhs_evals']} | {r['steps']} | "
                  f"{float(r['jellett_drift']):.1e} | {r['verdict']} | {'yes' if r['verdict_ok'] == '1' else 'NO'} | "
                  f"{1e3 * float(r['verdict_time_s']):.3g} |")
        print("\nCheapest run reaching each error level (best front) and the SciPy ratio:\n")
        print("| error <= | tippe best | tippe rk8pd | SciPy best | SciPy / tippe |")
        print("|---|---|---|---|---|")
        for lv in LEVELS:
            tb = cheapest(ws, lv)
            t8 = cheapest(ws, lv, "rk8pd")
            sb = cheapest(ss, lv)
            ratio = (f"{float(sb['time_s']) / float(tb['time_s']):.0f}"
                     if tb and sb else "n/a")
            print(f"| {lv:.0e} | {fmt_run(tb)} | {fmt_run(t8)} | {fmt_run(sb)} | {ratio} |")
        bad = [r for r in ws if ok(r) and r["verdict_ok"] == "0"]
        nok = len([r for r in ws if ok(r)])
        print(f"\nWrong verdicts: {len(bad)} of {nok} runs"
              + (": " + ", ".join(f"{r['stepper']} {float(r['rtol']):.0e} ({r['verdict']})"
                                  for r in bad) if bad else "") + ".")
        skipped = sorted({r["stepper"] for r in ws if r["status"] in ("skipped", "budget", "failed")})
        if skipped:
            print(f"Capped (tighter tolerances skipped or step budget hit): {', '.join(skipped)}.")


if __name__ == "__main__":
    main()
