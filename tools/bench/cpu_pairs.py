#!/usr/bin/python3
"""CPU time (user + sys) of two commands run alternately, for side-by-side
comparisons on a shared machine, where wall times follow the other jobs.

    /usr/bin/python3 tools/bench/cpu_pairs.py REPEATS BASE_COMMAND -- NEW_COMMAND

Each command is one string (split on spaces), run REPEATS times, base and new
alternating, with output discarded; prints every CPU time, the medians and
base / new. CPU time is getrusage(RUSAGE_CHILDREN) of the whole process.
"""
import resource
import statistics
import subprocess
import sys


def cpu_of(argv):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def main():
    if len(sys.argv) < 5 or "--" not in sys.argv:
        sys.exit(__doc__)
    reps = int(sys.argv[1])
    cut = sys.argv.index("--")
    base = " ".join(sys.argv[2:cut]).split()
    new = " ".join(sys.argv[cut + 1:]).split()
    times = {"base": [], "new": []}
    for _ in range(reps):
        times["base"].append(cpu_of(base))
        times["new"].append(cpu_of(new))
    for k in ("base", "new"):
        print(f"{k:4s} CPU s: " + " ".join(f"{t:.3f}" for t in times[k])
              + f"  median {statistics.median(times[k]):.3f}")
    print(f"base / new (medians): "
          f"{statistics.median(times['base']) / statistics.median(times['new']):.2f}")


if __name__ == "__main__":
    main()
