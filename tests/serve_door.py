#!/usr/bin/env python3
"""tippe serve's door against what issue 36 tried: a request cannot forge a log
line (%0a), no answer carries bytes that are not UTF-8 (a request's invalid
UTF-8, a character cut by a bounded quote), \\u0000 in a string is refused, a
number beyond a double is "not finite" with its field, a chunked body is cut at
the 1 MiB cap, two Host headers are a 400, a server on port 80 takes a Host
without the port, and slow connections (300 trickling their headers) do not
keep a real client out. Loopback only, bounded in count and time.

Usage: serve_door.py TIPPE. Prints 'N passed, M failed'."""
import json
import os
import socket
import sys
import time

from serve_lib import Server, REPO, check, finish

tippe = sys.argv[1]


def raw_request(srv, data, timeout=10):
    """Sends bytes as they are; returns what the server answered (bytes)."""
    s = socket.create_connection((srv.host, srv.port), timeout=timeout)
    s.sendall(data)
    out = b""
    try:
        while True:
            b = s.recv(65536)
            if not b:
                break
            out += b
            if b"\r\n\r\n" in out:
                head, _, body = out.partition(b"\r\n\r\n")
                n = [int(l.split(b":")[1]) for l in head.split(b"\r\n")
                     if l.lower().startswith(b"content-length:")]
                if n and len(body) >= n[0]:
                    break
    except socket.timeout:
        pass
    s.close()
    return out


def post_raw(srv, path, body):
    """POST body (bytes) as JSON: (status, body bytes)."""
    head = ("POST %s HTTP/1.1\r\nHost: %s:%d\r\nContent-Type: application/json\r\n"
            "Content-Length: %d\r\nConnection: close\r\n\r\n" % (path, srv.host, srv.port,
                                                                len(body))).encode()
    out = raw_request(srv, head + body)
    head, _, data = out.partition(b"\r\n\r\n")
    status = int(head.split(b" ")[1]) if head.startswith(b"HTTP/") else 0
    return status, data


def utf8(data):
    try:
        data.decode("utf-8", errors="strict")
        return True
    except UnicodeDecodeError:
        return False


with Server(tippe) as srv:
    # ---- the log: a percent-decoded newline stays in its line
    st, _, _ = srv.request("GET", "/api/designs/x%0aFORGED%20line%0d%0a")
    time.sleep(0.2)
    log = open(srv.log, "rb").read()
    lines = log.split(b"\n")
    check(st == 404 and not any(l.startswith(b"FORGED") for l in lines) and
          b"\\x0aFORGED" in log,
          "%0a in a URL is escaped in the log (\\x0a), no forged line")

    # ---- answers are UTF-8: a request's invalid bytes, a bounded quote cutting a character
    st, data = post_raw(srv, "/api/sweep", b'{"design": "\xff\xfe m12"}')
    check(st == 400 and utf8(data) and "\ufffd" in json.loads(data)["error"],
          "a design name of invalid UTF-8: 400, the answer UTF-8 with U+FFFD (%s)" %
          data[:90].decode("utf-8", "replace"))
    name = "a" * 79 + "\u00e9"  # the 80th byte is the first of two
    st, data = post_raw(srv, "/api/sweep", json.dumps({"design": name}).encode())
    check(st == 400 and utf8(data),
          "a name whose 80th byte starts a character: the cut quote is UTF-8")
    st, data = post_raw(srv, "/api/sweep", b'{"design": "m12-setscrew", "\xc3": 1}')
    check(st == 400 and utf8(data), "an unknown key of invalid UTF-8: the answer is UTF-8")

    # ---- \u0000 would cut a string where the checks read it
    st, _, o = srv.post("/api/sweep", '{"design": "m12-setscrew\\u0000../../etc/passwd"}')
    check(st == 400 and "\\u0000" in o.get("error", ""),
          "\\u0000 in a string: 400 (%s)" % o.get("error", "")[:60])
    st, _, o = srv.post("/api/sweep", '{"design": "m12-setscrew", "x\\\\u0000": 1}')
    check(st == 400 and o.get("field") == "x\\u0000",
          "an escaped backslash before u0000 is text, not a NUL (the key is unknown)")

    # ---- 1e999: not finite, named where it is
    m12 = open(os.path.join(REPO, "designs/m12-setscrew.json")).read()
    design = json.loads(m12)
    text = json.dumps({"design": design}).replace('"radius_mm": 25', '"radius_mm": 1e999', 1)
    st, _, o = srv.post("/api/sweep", text)
    check(st == 400 and "finite" in o.get("error", "") and o.get("field") == "design.radius_mm",
          "1e999 in a design: 400 'not finite', field %s (%s)" %
          (o.get("field"), o.get("error", "")[:60]))
    st, _, o = srv.post("/api/eval", '{"design": "m12-setscrew", "z2_mm": -1e999}')
    check(st == 400 and "finite" in o.get("error", "") and o.get("field") == "z2_mm",
          "-1e999 as z2_mm: 400 'not finite' (%s)" % o.get("error", "")[:60])

    # ---- a chunked body has no length: cut at the cap, not read to its end
    s = socket.create_connection((srv.host, srv.port), timeout=10)
    s.sendall(("POST /api/sweep HTTP/1.1\r\nHost: %s:%d\r\nContent-Type: application/json\r\n"
               "Transfer-Encoding: chunked\r\n\r\n" % (srv.host, srv.port)).encode())
    chunk = b"%x\r\n%s\r\n" % (1 << 16, b" " * (1 << 16))
    sent, t0, cut = 0, time.time(), False
    limit = 64 << 20  # without the cut the server reads all of it
    try:
        while sent < limit and time.time() - t0 < 60:
            s.sendall(chunk)
            sent += 1 << 16
    except (BrokenPipeError, ConnectionResetError, socket.timeout):
        cut = True
    if not cut:  # everything fit in the socket's buffers: has the server closed?
        s.settimeout(5)
        try:
            cut = s.recv(100) in (b"",) or True
        except (ConnectionResetError, socket.timeout):
            cut = False
    s.close()
    check(cut and sent < 32 << 20,
          "a chunked body over 1 MiB: the connection is closed at the cap (%.1f MiB sent)" %
          (sent / 2**20))
    st, _, _ = srv.request("GET", "/api/designs")
    check(st == 200, "still serving")

    # ---- two Host headers
    out = raw_request(srv, ("GET /api/designs HTTP/1.1\r\nHost: %s:%d\r\nHost: evil.example\r\n"
                            "Connection: close\r\n\r\n" % (srv.host, srv.port)).encode())
    check(out.startswith(b"HTTP/1.1 400"), "two Host headers: 400 (%s)" % out[:12])

# ---- slow connections: 300 from one address (a machine on the LAN) trickling their headers
with Server(tippe) as srv:
    slow, refused = [], 0
    t0 = time.time()
    for i in range(300):
        try:
            c = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            c.settimeout(2)
            c.bind(("127.0.0.2", 0))
            c.connect((srv.host, srv.port))
            c.sendall(b"GET /api/designs HTTP/1.1\r\n")
            slow.append(c)
        except OSError:
            refused += 1
    time.sleep(0.5)
    for c in slow:  # a header byte now and then, never the end of the headers
        try:
            c.sendall(b"X")
        except OSError:
            pass
    t1 = time.time()
    try:
        st, _, _ = srv.request("GET", "/api/designs", timeout=5)
    except OSError as e:
        st = str(e)
    st2, _, _ = srv.post("/api/sweep", {"design": "m12-setscrew"}, timeout=30) if st == 200 \
        else (0, 0, 0)
    check(st == 200 and st2 == 200 and time.time() - t1 < 5,
          "300 slow connections from 127.0.0.2 (%d opened): a client on 127.0.0.1 is served "
          "(%s, sweep %s, %.2f s)" % (len(slow), st, st2, time.time() - t1))
    # the headers are due within 10 s: a connection still trickling is closed by then
    alive, t_closed = True, None
    c = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    c.bind(("127.0.0.3", 0))
    c.connect((srv.host, srv.port))
    c.settimeout(1)
    start = time.time()
    c.sendall(b"GET /api/designs HTTP/1.1\r\n")
    while time.time() - start < 16 and alive:
        try:
            c.sendall(b"X-Slow: 1\r\n")
            if c.recv(100) == b"":
                alive = False
        except socket.timeout:
            pass
        except OSError:
            alive = False
    t_closed = time.time() - start
    c.close()
    check(not alive and 9 < t_closed < 12,
          "a connection trickling its headers is closed at 10 s (%.1f s%s)" %
          (t_closed, "" if not alive else ", still open"))
    for c in slow:
        c.close()

# ---- port 80: a browser sends Host without the port
try:
    with Server(tippe, listen="127.0.0.1:80") as srv:
        st, _, _ = srv.request("GET", "/api/designs", headers={"Host": "127.0.0.1"})
        st2, _, _ = srv.request("GET", "/api/designs", headers={"Host": "localhost"})
        st3, _, _ = srv.request("GET", "/api/designs", headers={"Host": "evil.example"})
        check(st == 200 and st2 == 200 and st3 == 403,
              "--listen 127.0.0.1:80: Host 127.0.0.1 and localhost without the port served "
              "(%d, %d), a foreign Host still refused (%d)" % (st, st2, st3))
except RuntimeError as e:
    print("skip port 80 (cannot listen there: %s)" % str(e).strip()[-80:])

finish()
