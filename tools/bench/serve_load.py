#!/usr/bin/env python3
"""Load benchmark of tippe serve (a benchmark, not a test: it measures).

CLIENTS clients (default 16) each open a shipped design (--designs solid, printed
or all) and edit it as a person at the page would, for SECONDS (default 60): a
printed design gets a new infill for its printed part, a solid one a sphere
radius up to 1 mm larger. After each edit a client asks what the page asks
(--mix page, the default): the sweep (POST /api/sweep) and with it the build
sheet's verdict (/api/verdict, on a second connection), then the advice (/api/advice) on a connection of its own,
which it closes unanswered when its next edit comes (the page aborts it); with
--mix sweep, the sweep alone. It then waits THINK seconds (default 0: as fast as
it can). The server runs with its defaults (one worker per core, a queue of 16 per
worker); a client that gets 503 busy waits its Retry-After and tries again, and
counts it. Prints each request's p50, p95 and max round trip, the requests, the
errors (any answer but 200 and 503 busy, or a broken connection), the 503s, the
advice answered and abandoned, the load average, and the server's resident memory
(VmRSS) at the start, its maximum and at each fifth of the run.

Usage: tools/bench/serve_load.py TIPPE [--clients N] [--seconds S] [--think S]
                                      [--designs solid|printed|all] [--mix page|sweep]"""
import argparse
import http.client
import json
import os
import random
import re
import select
import signal
import socket
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
ap.add_argument("--mix", choices=("page", "sweep"), default="page")
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

lat = {"/api/sweep": [], "/api/verdict": []}
codes, lock = {}, threading.Lock()
advice = {"answered": 0, "abandoned": 0}
stop_at = time.time() + a.seconds
HEAD = "POST /api/advice HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Type: application/json\r\n" \
       "Content-Length: %d\r\nConnection: close\r\n\r\n"


def post(c, path, body):
    """(status, seconds, connection): c is replaced when it broke."""
    t0 = time.perf_counter()
    try:
        c.request("POST", path, body, {"Content-Type": "application/json",
                                       "Host": "127.0.0.1:%d" % port})
        r = c.getresponse()
        r.read()
        code, retry = r.status, float(r.getheader("Retry-After") or 1)
    except Exception as e:  # a broken connection is an error
        code, retry = "exception " + type(e).__name__, 1
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    dt = time.perf_counter() - t0
    with lock:
        codes[code] = codes.get(code, 0) + 1
        if code == 200:
            lat[path].append(dt)
    return code, retry, c


def advice_done(pending):
    """Whether the advice asked on pending (socket, t0) has its whole answer; its time kept."""
    sock, _, data = pending
    try:
        while select.select([sock], [], [], 0)[0]:
            b = sock.recv(65536)
            if not b:
                break
            data += b
    except OSError as e:  # a broken connection is an error
        with lock:
            k = "exception " + type(e).__name__
            codes[k] = codes.get(k, 0) + 1
        return True
    pending[2] = data
    head, _, body = data.partition(b"\r\n\r\n")
    n = re.search(rb"Content-Length: (\d+)", head)
    if not n or len(body) < int(n.group(1)):
        return False
    with lock:
        advice["answered"] += 1
        code = int(head.split()[1])
        codes[code] = codes.get(code, 0) + 1
    return True  # (its time is not known: it is looked at only at the next edit)


def client(n):
    rng = random.Random(n)
    name, d, i = designs[n % len(designs)]
    d = json.loads(json.dumps(d))
    R = d["radius_mm"]
    if i is not None and d["parts"][i]["print"] is True:
        d["parts"][i]["print"] = {}
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    cv = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    pending = None
    while time.time() < stop_at:
        if i is not None:
            d["parts"][i]["print"]["infill"] = round(rng.uniform(0.05, 0.6), 3)
        else:
            d["radius_mm"] = round(R + rng.uniform(0, 1), 3)
        body = json.dumps({"design": d})
        if pending and not advice_done(pending):  # the page aborts it at the next edit
            with lock:
                advice["abandoned"] += 1
        if pending:
            pending[0].close()
            pending = None
        if a.mix == "page":  # the verdict is asked with the sweep, as the page does
            vres = []
            vt = threading.Thread(target=lambda: vres.append(post(cv, "/api/verdict", body)))
            vt.start()
        code, retry, c = post(c, "/api/sweep", body)
        if a.mix == "page":
            vt.join()
            vcode, vretry, cv = vres[0]
            if code == 200:
                code, retry = vcode, vretry
            if code == 200:
                sock = socket.create_connection(("127.0.0.1", port))
                sock.sendall((HEAD % (port, len(body))).encode() + body.encode())
                pending = [sock, time.perf_counter(), b""]
        if code == 503:
            time.sleep(retry)
        elif a.think:
            time.sleep(a.think)
    if pending:
        if not advice_done(pending):
            with lock:
                advice["abandoned"] += 1
        pending[0].close()


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

load = os.getloadavg()
errors = sum(v for k, v in codes.items() if k not in (200, 503))
print("%s designs (%d), clients %d, think %g s, %.0f s, %d cores, mix %s; load average %.1f, "
      "%.1f, %.1f at the end" % (a.designs, len(designs), a.clients, a.think, a.seconds,
                               os.cpu_count(), a.mix, *load))
for path, v in lat.items():
    if not v and path != "/api/sweep":
        continue
    v.sort()
    q = lambda p: v[min(len(v) - 1, int(p * len(v)))] * 1e3 if v else float("nan")
    print("%-13s %5d answered (%.1f per second): p50 %.1f ms, p95 %.1f ms, max %.1f ms" %
          (path, len(v), len(v) / a.seconds, q(0.5), q(0.95), q(1.0)))
if a.mix == "page":
    print("advice: %d answered, %d abandoned at the next edit" % (advice["answered"],
                                                                 advice["abandoned"]))
print("answers: %s; errors %d" % (dict(sorted(codes.items(), key=str)), errors))
print("server memory (VmRSS): start %.1f MiB, max %.1f MiB, end %.1f MiB; at each fifth of "
      "the run: %s MiB" % (rss[0] / 1024, max(rss) / 1024, rss[-1] / 1024,
                          ", ".join("%.1f" % (rss[min(len(rss) - 1, k * len(rss) // 5)] / 1024)
                                    for k in range(1, 6))))
print("server exit status %d" % srv.returncode)
sys.exit(1 if errors else 0)
