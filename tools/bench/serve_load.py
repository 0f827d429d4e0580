#!/usr/bin/env python3
"""Load benchmark of tippe serve (a benchmark, not a test: it measures).

CLIENTS clients (default 16) each open a shipped design (--designs solid, printed
or all) and edit it as a person at the page would, for SECONDS (default 60): a
printed design gets a new infill for its printed part, a solid one a sphere
radius up to 1 mm larger, and the client asks for the sweep (POST /api/sweep, the
page's live request), then waits THINK seconds (default 0: as fast as it can). The
server runs with its defaults (one worker per core, a queue of 16 per worker);
a client that gets 503 busy waits its Retry-After and tries again, and counts it.
Prints the sweep round trip's p50, p95 and max, the requests, the errors (any
answer but 200 and 503 busy, or a broken connection), the 503s, and the
server's resident memory (VmRSS) at the start, its maximum and at the end.

Usage: tools/bench/serve_load.py TIPPE [--clients N] [--seconds S] [--think S]
                                      [--designs solid|printed|all]"""
import argparse
import http.client
import json
import os
import random
import re
import signal
import subprocess
import sys
import threading
import time

repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ap = argparse.ArgumentParser()
ap.add_argument("tippe")
ap.add_argument("--clients", type=int, default=16)
ap.add_argument("--seconds", type=float, default=60)
ap.add_argument("--think", type=float, default=0.0)
ap.add_argument("--designs", choices=("solid", "printed", "all"), default="all")
a = ap.parse_args()

log = open("/tmp/serve_load.log", "w")
srv = subprocess.Popen([a.tippe, "serve", "--listen", "127.0.0.1:0"], stderr=log,
                       stdout=subprocess.DEVNULL, cwd=repo)
port = None
for _ in range(200):
    m = re.search(r"http://127\.0\.0\.1:(\d+)/", open("/tmp/serve_load.log").read())
    if m:
        port = int(m.group(1))
        break
    time.sleep(0.05)
if not port:
    sys.exit("the server printed no URL")


def rss_kib():
    for line in open("/proc/%d/status" % srv.pid):
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


designs = []
for f in sorted(os.listdir(os.path.join(repo, "designs"))):
    if not f.endswith(".json"):
        continue
    d = json.load(open(os.path.join(repo, "designs", f)))
    if "parts" not in d:
        continue
    printed = [k for k, p in enumerate(d["parts"]) if p.get("print")]
    if (a.designs == "printed" and not printed) or (a.designs == "solid" and printed):
        continue
    designs.append((f, d, printed[0] if printed else None))

lat, codes, lock = [], {}, threading.Lock()
stop_at = time.time() + a.seconds


def client(n):
    rng = random.Random(n)
    name, d, i = designs[n % len(designs)]
    d = json.loads(json.dumps(d))
    R = d["radius_mm"]
    if i is not None and d["parts"][i]["print"] is True:
        d["parts"][i]["print"] = {}
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    while time.time() < stop_at:
        if i is not None:
            d["parts"][i]["print"]["infill"] = round(rng.uniform(0.05, 0.6), 3)
        else:
            d["radius_mm"] = round(R + rng.uniform(0, 1), 3)
        body = json.dumps({"design": d})
        t0 = time.perf_counter()
        try:
            c.request("POST", "/api/sweep", body, {"Content-Type": "application/json",
                                                   "Host": "127.0.0.1:%d" % port})
            r = c.getresponse()
            data = r.read()
            code = r.status
        except Exception as e:  # a broken connection is an error
            code = "exception " + type(e).__name__
            c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
        dt = time.perf_counter() - t0
        with lock:
            codes[code] = codes.get(code, 0) + 1
            if code == 200:
                lat.append(dt)
        if code == 503:
            time.sleep(float(r.getheader("Retry-After") or 1))
        elif a.think:
            time.sleep(a.think)


rss = [rss_kib()]
threads = [threading.Thread(target=client, args=(n,)) for n in range(a.clients)]
for t in threads:
    t.start()
while any(t.is_alive() for t in threads):
    time.sleep(1)
    rss.append(rss_kib())
for t in threads:
    t.join()
srv.send_signal(signal.SIGTERM)
srv.wait(timeout=60)

lat.sort()
q = lambda p: lat[min(len(lat) - 1, int(p * len(lat)))] * 1e3 if lat else float("nan")
errors = sum(v for k, v in codes.items() if k not in (200, 503))
print("%s designs (%d), clients %d, think %g s, %.0f s, %d cores: %d sweeps answered (%.1f per "
      "second)" % (a.designs, len(designs), a.clients, a.think, a.seconds, os.cpu_count(),
                   len(lat), len(lat) / a.seconds))
print("sweep round trip: p50 %.1f ms, p95 %.1f ms, max %.1f ms" % (q(0.5), q(0.95), q(1.0)))
print("answers: %s; errors %d" % (dict(sorted(codes.items(), key=str)), errors))
print("server memory (VmRSS): start %.1f MiB, max %.1f MiB, end %.1f MiB; at each fifth of "
      "the run: %s MiB" % (rss[0] / 1024, max(rss) / 1024, rss[-1] / 1024,
                          ", ".join("%.1f" % (rss[min(len(rss) - 1, k * len(rss) // 5)] / 1024)
                                    for k in range(1, 6))))
print("server exit status %d" % srv.returncode)
sys.exit(1 if errors else 0)
