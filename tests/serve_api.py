#!/usr/bin/env python3
"""tippe serve's API against the command's --json, on every shipped design (the
same numbers: the same library builders), and the server's safety: bad input
gets a 4xx JSON error naming the field and the server keeps serving; a foreign
Host or Origin, a cross-site request, a missing token off loopback and a path
with '..' are refused; a full queue gets 503 with Retry-After, a request over
its budget a 503; SIGTERM stops it with no temporary left.

Usage: serve_api.py TIPPE. Prints 'N passed, M failed'."""
import glob
import io
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
import zipfile

from serve_lib import Server, REPO, check, finish

tippe = sys.argv[1]


def cli(*args, json_out=True):
    r = subprocess.run([tippe] + list(args) + (["--json"] if json_out else []),
                       capture_output=True, text=True, cwd=REPO)
    if r.returncode:
        raise RuntimeError("tippe %s: %s" % (" ".join(args), r.stderr))
    return json.loads(r.stdout) if json_out else r.stdout


def same(api, ref, skip=("file", "set")):
    """The keys both give, equal (numbers exactly: the same code ran)."""
    bad = [k for k in ref if k not in skip and api.get(k) != ref[k]]
    return bad


def designs():
    out = []
    for path in sorted(glob.glob(os.path.join(REPO, "designs", "*.json"))):
        text = open(path).read()
        if '"parts"' in text:
            out.append(os.path.splitext(os.path.basename(path))[0])
    return sorted(out)


names = designs()

with Server(tippe) as srv:
    # ---- the lists
    st, _, lst = srv.request("GET", "/api/designs")
    check(st == 200 and [d["name"] for d in lst["designs"]] == names,
          "GET /api/designs lists the %d shipped designs" % len(names))
    st, hdrs, text = srv.request("GET", "/api/designs/m12-setscrew", raw=True)
    check(st == 200 and text == open(os.path.join(REPO, "designs/m12-setscrew.json"), "rb").read(),
          "GET /api/designs/m12-setscrew is the file's text")
    st, _, mats = srv.request("GET", "/api/materials")
    ref = cli("materials")
    check(st == 200 and mats["materials"] == ref["materials"],
          "GET /api/materials is tippe materials --json's table")

    # ---- every shipped design: sweep, eval, check against the command
    t0 = time.time()
    for name in names:
        path = "designs/%s.json" % name
        design = json.load(open(os.path.join(REPO, path)))
        st, _, sw = srv.post("/api/sweep", {"design": design})
        ref = cli("sweep", path)
        bad = same(sw, ref) if st == 200 else ["status %d: %s" % (st, sw)]
        check(not bad and "curve" in sw, "sweep %s: as tippe sweep --json%s" %
              (name, "" if not bad else " except " + ", ".join(map(str, bad[:4]))))
        a, b = ref["travel_mm"]
        z2 = round(0.5 * (a + b), 3)
        st, _, ev = srv.post("/api/eval", {"design": name, "z2_mm": z2})
        ref = cli("eval", path, "--z2", repr(z2))
        bad = same(ev, ref) if st == 200 else ["status %d" % st]
        check(not bad, "eval %s at %g mm: as tippe eval --json%s" %
              (name, z2, "" if not bad else " except " + ", ".join(bad[:4])))
        st, _, ck = srv.post("/api/check", {"design": design, "z2_mm": z2, "spin_rev_s": 20})
        ref = cli("check", path, "--z2", repr(z2), "--spin", "20rev/s")
        bad = same(ck, ref) if st == 200 else ["status %d: %s" % (st, ck)]
        check(not bad and len(ck["theta_samples"]["t_s"]) > 10,
              "check %s at %g mm, 20 rev/s: %s as tippe check --json%s" %
              (name, z2, ck.get("verdict"), "" if not bad else " except " + ", ".join(bad[:4])))
    print("     (%d designs in %.1f s)" % (len(names), time.time() - t0))

    # ---- the patch law: as tippe check --friction patch (Hertz on the table, or a radius),
    # with the radius sensitivity as the command gives it, or without ("off")
    for extra, flags in (({"table": "glass"}, ["--table", "glass"]),
                         ({"patch_mm": 0.3}, ["--patch-mm", "0.3"]),
                         ({"radius_sensitivity": "off"}, ["--no-radius-sensitivity"])):
        req = dict({"design": "m12-setscrew", "z2_mm": 5, "spin_rev_s": 15, "friction": "patch"},
                   **extra)
        st, _, ck = srv.post("/api/check", req)
        ref = cli("check", "designs/m12-setscrew.json", "--z2", "5", "--spin", "15rev/s",
                  "--friction", "patch", "--t-end", "600", *flags)
        if st == 200 and "radius_sensitivity" not in extra:
            check(ck.get("radius_sensitivity") and len(ck["radius_sensitivity"]["runs"]) == 3,
                  "check, patch law %s: the radius sensitivity's three runs" % extra)
        bad = same(ck, ref) if st == 200 else ["status %d: %s" % (st, ck)]
        check(not bad, "check, patch law %s: as tippe check --json%s" %
              (extra, "" if not bad else " except " + ", ".join(map(str, bad[:4]))))

    # ---- compare: each design's sweep
    st, _, cmp = srv.post("/api/compare", {"designs": ["m12-setscrew", "m3-setscrew"]})
    ok = st == 200 and len(cmp["designs"]) == 2
    for i, n in enumerate(["m12-setscrew", "m3-setscrew"]):
        ok = ok and not same(cmp["designs"][i], cli("sweep", "designs/%s.json" % n))
    check(ok, "compare m12 and m3: each as tippe sweep --json")

    # ---- build: tippe build's files, in one zip
    st, hdrs, data = srv.post("/api/build", {"design": "m12-setscrew"}, raw=True)
    names_zip = sorted(zipfile.ZipFile(io.BytesIO(data)).namelist()) if st == 200 else []
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([tippe, "build", "designs/m12-setscrew.json", "-o", d], cwd=REPO,
                       capture_output=True, check=True)
        # and the design itself, as STEM.json (issue 37: the zip holds what it was made of)
        want = sorted(os.listdir(d) + ["m12-setscrew.json"])
        built = json.load(open(os.path.join(d, "m12-setscrew-build.json")))
    check(st == 200 and hdrs["content-type"] == "application/zip" and names_zip == want and
          "m12-setscrew-build.zip" in hdrs.get("content-disposition", ""),
          "build m12-setscrew: the zip holds what tippe build writes (%d files) and the "
          "design" % len(want))
    check(st == 200 and zipfile.ZipFile(io.BytesIO(data)).read("m12-setscrew.json") ==
          open(os.path.join(REPO, "designs", "m12-setscrew.json"), "rb").read(),
          "build m12-setscrew: the design in the zip is the shipped file, byte for byte")
    if st == 200:
        sheet = json.loads(zipfile.ZipFile(io.BytesIO(data)).read("m12-setscrew-build.json"))
        check(same(sheet, built, skip=("file",)) == [],
              "build m12-setscrew: its sheet (JSON) is tippe build's")

    # ---- the sheet's verdict: tippe build's, computed without files (the verdict alone;
    # the advice, with the launch checks, on its own)
    st, _, v = srv.post("/api/verdict", {"design": "m12-setscrew"})
    check(st == 200 and v["verdict"] == built["verdict"] and
          v["settable"] == built["settable"] and
          v["min_setting_mm"] == built["min_setting_mm"] and "advice" not in v,
          "verdict m12-setscrew: '%s', its settable widths as tippe build's" %
          (v.get("verdict") if st == 200 else st))
    st, _, a = srv.post("/api/advice", {"design": "m12-setscrew"})
    check(st == 200 and a["verdict"] == built["verdict"] and
          a["advice"] == [x["advice"] for x in built.get("to_make_it_settable", [])],
          "advice m12-setscrew: its changes as tippe build's (%d)" %
          (len(a.get("advice", [])) if st == 200 else st))
    # every shipped design: the cheap verdict is the whole sheet's
    bad = []
    for name in names:
        st, _, v = srv.post("/api/verdict", {"design": name})
        st2, _, a = srv.post("/api/advice", {"design": name})
        if st != 200 or st2 != 200:
            bad.append("%s (status %d, %d)" % (name, st, st2))
        elif any(v[k] != a[k] for k in v if k != "text"):
            bad.append("%s (%s)" % (name, ", ".join("%s: %r against %r" % (k, v[k], a.get(k))
                                                    for k in v if k != "text" and v[k] != a.get(k))))
    check(not bad, "every shipped design: /api/verdict as /api/advice's whole sheet%s" %
          ("" if not bad else " except " + ", ".join(bad)))
    st, _, e = srv.post("/api/verdict", {"design": "m12-setscrew", "z2_mm": 3})
    check(st == 400 and e.get("field") == "z2_mm", "verdict: an unknown field is a 400 naming it")

    # ---- a film
    for fmt, magic in (("webm", b"\x1a\x45\xdf\xa3"), ("gif", b"GIF8")):
        st, hdrs, data = srv.post("/api/animate", {"design": "m12-setscrew", "z2_mm": 10,
                                                   "format": fmt, "seconds": 2,
                                                   "width_px": 160, "height_px": 120}, raw=True)
        check(st == 200 and data[:4] == magic, "animate: a %s film (%d bytes)" % (fmt, len(data)))

    # ---- bad input: 4xx JSON naming the field, and the server keeps serving
    m12 = json.load(open(os.path.join(REPO, "designs/m12-setscrew.json")))
    wrong_type = json.loads(json.dumps(m12))
    wrong_type["parts"][2]["height_mm"] = "fifteen"
    unknown = json.loads(json.dumps(m12))
    unknown["parts"][2]["colour"] = "red"
    huge = json.loads(json.dumps(m12))
    huge["radius_mm"] = 1e308
    # issue 36: a part's G-code named by path was opened on the server's disk
    gcode_path = json.loads(json.dumps(m12))
    gcode_path["parts"][0]["print"] = {"gcode": "/etc/passwd"}
    # issue 37: an upload's id that the server does not keep
    gcode_gone = json.loads(json.dumps(m12))
    gcode_gone["parts"][0]["print"] = {"gcode": "upload:0123456789abcdef"}
    bad_inputs = [
        ("malformed JSON", "/api/sweep", '{"design": "m12-setscrew",', 400, None),
        ("not an object", "/api/sweep", '[1, 2]', 400, None),
        ("a wrong type", "/api/eval", {"design": "m12-setscrew", "z2_mm": "ten"}, 400, "z2_mm"),
        ("a wrong type in the design", "/api/sweep", {"design": wrong_type}, 400,
         "design.parts[2].height_mm"),
        ("an unknown field", "/api/sweep", {"design": "m12-setscrew", "colour": 1}, 400, "colour"),
        ("an unknown field in the design", "/api/sweep", {"design": unknown}, 400, "design.parts[2]"),
        ("a huge number", "/api/eval", {"design": "m12-setscrew", "z2_mm": 1e308}, 400, "z2_mm"),
        ("a number beyond double", "/api/eval", '{"design": "m12-setscrew", "z2_mm": 1e999}', 400,
         "z2_mm"),
        ("a huge radius", "/api/sweep", {"design": huge}, 400, "design.radius_mm"),
        ("a design not shipped", "/api/sweep", {"design": "../../etc/passwd"}, 400, "design"),
        ("a materials file named", "/api/sweep",
         {"design": dict(m12, materials="/etc/passwd")}, 400, "design.materials"),
        ("a G-code file named", "/api/sweep", {"design": gcode_path}, 400,
         "design.parts[0].print.gcode"),
        ("an upload not kept", "/api/sweep", {"design": gcode_gone}, 400,
         "design.parts[0].print.gcode"),
        ("a 10 MB body", "/api/sweep", " " * (10 << 20), 413, None),
        ("10^6-deep arrays", "/api/sweep", '{"a":' + "[" * 10**6 + "]" * 10**6 + "}", 413, None),
        ("400000-deep arrays", "/api/sweep", "[" * 400000 + "]" * 400000, 400, None),
        ("a film too long", "/api/animate", {"design": "m12-setscrew", "z2_mm": 10,
                                             "seconds": 600}, 400, "seconds"),
        ("a film too large", "/api/animate", {"design": "m12-setscrew", "z2_mm": 10,
                                              "width_px": 4000}, 400, "width_px"),
        ("a Z2 outside the travel", "/api/check", {"design": "m12-setscrew", "z2_mm": 500}, 400,
         "z2_mm"),
        ("a table without the patch law", "/api/check",
         {"design": "m12-setscrew", "z2_mm": 5, "table": "glass"}, 400, "table"),
        ("an unknown table", "/api/check",
         {"design": "m12-setscrew", "z2_mm": 5, "friction": "patch", "table": "ice"}, 400, "table"),
        ("a patch of 1 m", "/api/check",
         {"design": "m12-setscrew", "z2_mm": 5, "friction": "patch", "patch_mm": 1000}, 400,
         "patch_mm"),
        ("too many designs to compare", "/api/compare", {"designs": ["m12-setscrew"] * 9}, 400,
         "designs"),
    ]
    for what, path, body, want, field in bad_inputs:
        st, hdrs, o = srv.post(path, body)
        ok = st == want and isinstance(o, dict) and "error" in o
        # no refusal quotes a file of the server (the password file's first field)
        ok = ok and "root:" not in json.dumps(o)
        if field:
            ok = ok and (o.get("field") or "").startswith(field)
        st2, _, _ = srv.request("GET", "/api/designs")
        check(ok and st2 == 200, "%s: %d, field %s (%s); still serving" %
              (what, st, o.get("field") if isinstance(o, dict) else None,
               (o.get("error", "") if isinstance(o, dict) else str(o))[:70]))

    # ---- G-code uploads (issue 37): text/x-gcode only, read in memory, refused with its
    # field when it is not G-code; a JSON body is not an upload
    for what, body, ctype, want in [
            ("a JSON body", b'{"design": 1}', "application/json", 415),
            ("a NUL byte (binary G-code)", b"G1 X1\0", "text/x-gcode", 400),
            ("no extrusion", b"G28\nG1 X10 Y10\n", "text/x-gcode", 400),
            ("an empty body", b"", "text/x-gcode", 400)]:
        st, _, o = srv.request("POST", "/api/gcode?name=x.gcode", body,
                               headers={"Content-Type": ctype})
        check(st == want and isinstance(o, dict) and "error" in o and
              (want == 415 or o.get("field") == "gcode"),
              "an upload of %s: %d, field %s (%s)" % (what, st, o.get("field") if
                                                        isinstance(o, dict) else None,
                                                        (o.get("error", "") if isinstance(o, dict)
                                                         else str(o))[:70]))

    # ---- the doors
    doors = [
        ("a foreign Host", "GET", "/api/designs", None, {"Host": "evil.example:80"}, 403),
        ("a foreign Origin", "POST", "/api/sweep", {"design": "m12-setscrew"},
         {"Origin": "http://evil.example"}, 403),
        ("a null Origin", "POST", "/api/sweep", {"design": "m12-setscrew"}, {"Origin": "null"}, 403),
        ("a cross-site fetch", "GET", "/api/designs", None, {"Sec-Fetch-Site": "cross-site"}, 403),
        ("a form's content type", "POST", "/api/sweep", '{"design": "m12-setscrew"}',
         {"Content-Type": "text/plain"}, 415),
        ("a path with ..", "GET", "/../designs/materials.json", None, {}, 400),
        ("an escaped ..", "GET", "/api/designs/%2e%2e%2fmaterials", None, {}, 400),
        ("GET on an endpoint that takes POST", "GET", "/api/sweep", None, {}, 405),
        ("DELETE", "DELETE", "/api/designs", None, {}, 405),
        ("an unknown endpoint", "POST", "/api/shell", {}, {}, 404),
    ]
    for what, method, path, body, headers, want in doors:
        st, hdrs, o = srv.request(method, path, body, headers=headers)
        check(st == want and "access-control-allow-origin" not in hdrs,
              "%s: %d (%s)" % (what, st, (o.get("error", "") if isinstance(o, dict) else "")[:60]))
    st, hdrs, _ = srv.request("GET", "/", raw=True)
    check(st == 200 and "default-src 'self'" in hdrs.get("content-security-policy", "") and
          "access-control-allow-origin" not in hdrs, "the page: 200 with a strict CSP, no CORS")
    st, hdrs, o = srv.request("GET", "/api/designs", headers={"Host": "localhost:%d" % srv.port,
                                                              "Origin": "http://localhost:%d" % srv.port})
    check(st == 200, "the page's own origin (localhost) is served")
    code, left = srv.stop()
    check(code == 0 and not left, "SIGTERM: exit 0, no temporary left (%s)" % left)

# ---- off loopback: the token
with Server(tippe, listen="127.0.0.2:0") as srv:
    check(srv.token is not None and len(srv.token) >= 32,
          "127.0.0.2 (not the default loopback address): the URL carries a token")
    tok = srv.token
    srv.token = None
    st, _, o = srv.request("GET", "/api/designs")
    check(st == 403 and "token" in o["error"], "no token: 403 (%s)" % o["error"][:60])
    st, _, _ = srv.request("GET", "/api/designs", headers={"X-Tippe-Token": "0" * len(tok)})
    check(st == 403, "a wrong token: 403")
    st, _, _ = srv.request("GET", "/api/designs?token=" + tok)
    check(st == 200, "?token=: 200")
    st, hdrs, _ = srv.request("GET", "/?token=" + tok, raw=True)
    cookie = hdrs.get("set-cookie", "")
    check(st == 200 and "HttpOnly" in cookie and "SameSite=Strict" in cookie,
          "the page opened with its token sets a strict cookie")
    st, _, _ = srv.request("POST", "/api/sweep", {"design": "m12-setscrew"},
                           headers={"Cookie": cookie.split(";")[0]})
    check(st == 200, "the cookie opens the API")

# ---- a full queue and the budget
with Server(tippe, "--workers", "1", "--queue", "1", "--budget", "0.3") as srv:
    results = []

    def slow():
        results.append(srv.post("/api/build", {"design": "m12-setscrew"}, raw=True))

    threads = [threading.Thread(target=slow) for _ in range(4)]
    for t in threads:
        t.start()
        time.sleep(0.02)
    for t in threads:
        t.join()
    codes = sorted(r[0] for r in results)
    busy = [r for r in results if r[0] == 503 and b"busy" in r[2]]
    over = [r for r in results if r[0] == 503 and b"over budget" in r[2]]
    check(busy and all(r[1].get("retry-after") for r in busy),
          "4 builds at once on 1 worker and a queue of 1: 503 busy with Retry-After (%s)" % codes)
    check(over, "a build over a 0.3 s budget: 503 over budget")
    # the worker finishes the builds cut at their budget (their answers are dropped)
    for _ in range(60):
        st, _, _ = srv.post("/api/eval", {"design": "m12-setscrew", "z2_mm": 5})
        if st == 200:
            break
        time.sleep(0.5)
    check(st == 200, "then it serves again")
    code, left = srv.stop()
    check(code == 0 and not left, "SIGTERM after cut builds: exit 0, no temporary left (%s)" % left)

# ---- a stop during a build
with Server(tippe) as srv:
    t = threading.Thread(target=lambda: srv.post("/api/build", {"design": "shell-band"},
                                                 raw=True, timeout=60))
    t.start()
    time.sleep(0.3)
    code, left = srv.stop()
    t.join()
    check(code == 0 and not left, "SIGTERM during a build: exit 0, no temporary left (%s)" % left)

finish()
