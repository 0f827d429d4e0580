"""What the tests of tippe serve share: a server started on a free loopback port
(its URL read from what it prints), stopped with SIGTERM, and a small HTTP
client that sends what a test wants (headers, bodies) and returns the status,
headers and body."""
import http.client
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Server:
    """tippe serve on 127.0.0.1 with a free port and a private TMPDIR (so that a
    test can see that no temporary is left)."""

    def __init__(self, tippe, *args, listen="127.0.0.1:0"):
        self.tippe, self.args, self.listen = tippe, list(args), listen
        self.tmp = tempfile.mkdtemp(prefix="tippe-serve-test.")
        self.log = os.path.join(self.tmp, "server.log")

    def __enter__(self):
        env = dict(os.environ, TMPDIR=self.tmp)
        self.logf = open(self.log, "w")
        self.proc = subprocess.Popen([self.tippe, "serve", "--listen", self.listen] + self.args,
                                     stdout=subprocess.DEVNULL, stderr=self.logf, cwd=REPO,
                                     env=env)
        deadline = time.time() + 20
        while time.time() < deadline:
            text = open(self.log).read()
            m = re.search(r"(http://([0-9.]+|\[[0-9a-f:]+\]):(\d+)/(\?token=\w+)?)", text)
            if m:
                self.url, self.host, self.port = m.group(1), m.group(2), int(m.group(3))
                self.token = m.group(4)[7:] if m.group(4) else None
                return self
            if self.proc.poll() is not None:
                raise RuntimeError("tippe serve exited: " + text)
            time.sleep(0.05)
        raise RuntimeError("tippe serve printed no URL: " + open(self.log).read())

    def stop(self):
        """SIGTERM; returns the exit status and the temporaries left."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=60)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.logf.close()
        left = [f for f in os.listdir(self.tmp) if f != "server.log"]
        return self.proc.returncode, left

    def __exit__(self, *exc):
        self.stop()

    def request(self, method, path, body=None, headers=None, raw=False, timeout=120):
        """(status, headers, body as JSON, or bytes when raw or not JSON)."""
        c = http.client.HTTPConnection(self.host.strip("[]"), self.port, timeout=timeout)
        h = {"Host": "%s:%d" % (self.host, self.port)}
        if body is not None and not isinstance(body, (bytes, str)):
            body = json.dumps(body)
        if body is not None:
            h["Content-Type"] = "application/json"
        if self.token:
            h["X-Tippe-Token"] = self.token
        h.update(headers or {})
        for k in [k for k, v in h.items() if v is None]:
            del h[k]
        c.request(method, path, body=body, headers=h)
        r = c.getresponse()
        data = r.read()
        hdrs = {k.lower(): v for k, v in r.getheaders()}
        c.close()
        if not raw and hdrs.get("content-type", "").startswith("application/json"):
            return r.status, hdrs, json.loads(data)
        return r.status, hdrs, data

    def post(self, path, body, **kw):
        return self.request("POST", path, body, **kw)


# The zone ends are found to TIPPE_SWEEP_XTOL_MM (1e-7 mm, sweep.h); the server reads an
# uploaded G-code at 1 g/cm^3 and scales it to the material, the command reads the file at
# the material's density: the moments differ by rounding, which may move each end of a
# zone anywhere within its root's tolerance, so a robust width may differ by twice it.
GCODE_WIDTH_TOL_MM = 2e-7 + 1e-12


def same_verdict(page, sheet, tol_mm=0.0):
    """The page's /api/verdict against tippe build --json: the verdict, its two flags, the
    setting rule and each behaviour's reachability, robust width (within tol_mm: 0, the
    same library function on the same design, unless a G-code was uploaded) and
    settability. Returns '' when they agree, else what differs."""
    for k in ("verdict", "three_in_one", "settable", "min_setting_mm"):
        if page[k] != sheet[k]:
            return "%s: page %r, tippe build %r" % (k, page[k], sheet[k])
    if len(page["settings"]) != len(sheet["settings"]):
        return "settings: %d on the page, %d in the sheet" % (len(page["settings"]),
                                                             len(sheet["settings"]))
    for p, s in zip(page["settings"], sheet["settings"]):
        if p["behaviour"] != s["behaviour"] or p["reachable"] != s["reachable"]:
            return "%s: reachable %r on the page, %r in the sheet" % (s["behaviour"],
                                                                     p["reachable"], s["reachable"])
        if s["reachable"] and (abs(p["robust_width_mm"] - s["robust_width_mm"]) > tol_mm or
                               p["settable"] != s["settable"]):
            return "%s: robust %.9f mm (settable %r) on the page, %.9f mm (%r) in the sheet" % (
                s["behaviour"], p["robust_width_mm"], p["settable"], s["robust_width_mm"],
                s["settable"])
    return ""


# The tally every serve test prints: one line per check, "ok" or "FAIL", and a last
# line "N passed, M failed" (the test's exit status: 1 if any failed).
_tally = {"passed": 0, "failed": 0}


def check(ok, what):
    if ok:
        _tally["passed"] += 1
        print("ok   " + what)
    else:
        _tally["failed"] += 1
        print("FAIL " + what)


def console_errors(driver, allow_400=()):
    """The page's console errors and warnings since the last call (Chromium's log is
    drained by reading it), but for the lines of requests refused with a 400 whose URL
    holds one of allow_400: Chromium logs a refused request itself, and there a 400 is
    the server's answer, not a script error."""
    return [e for e in driver.get_log("browser") if e["level"] in ("SEVERE", "WARNING")
            and not (any(u in e["message"] for u in allow_400) and "400" in e["message"])]


def said(logs):
    """The first three console lines, to follow a check's words ('' when none)."""
    return "" if not logs else ": " + "; ".join(e["message"][:120] for e in logs[:3])


def finish():
    print("%d passed, %d failed" % (_tally["passed"], _tally["failed"]))
    sys.exit(1 if _tally["failed"] else 0)

