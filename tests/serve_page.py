#!/usr/bin/env python3
"""The maker's loop on tippe serve's page (issue 37), in headless Chromium: what the
page says holds (the headline's own state where the model does not hold, the sheet's
launch checks and pole fixes with their --set lines, the launch line's inputs and
warnings, the zone table's notes), compared with what the commands print for the same
design. A screenshot of each step is kept in ARTEFACTS.

Usage: serve_page.py TIPPE ARTEFACTS. Prints 'N passed, M failed'."""
import json
import os
import re
import subprocess
import sys
import time

from serve_lib import Server, REPO

tippe, artefacts = sys.argv[1], sys.argv[2]
os.makedirs(artefacts, exist_ok=True)

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

passed, failed = 0, 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print("ok   " + what)
    else:
        failed += 1
        print("FAIL " + what)


def cli(*args, json_out=True):
    r = subprocess.run([tippe] + list(args) + (["--json"] if json_out else []),
                       capture_output=True, text=True, cwd=REPO, check=True)
    return json.loads(r.stdout) if json_out else r.stdout


def sheet(design, *sets):
    args = ["build", "designs/%s.json" % design, "-o", os.path.join(artefacts, "build-cli"),
            "--no-export"]
    for s in sets:
        args += ["--set", s]
    return cli(*args)


def js(d, script):
    return d.execute_script(script)


def text(d, id_):
    return d.find_element(By.ID, id_).text


def open_design(d, wait, name):
    d.get(srv.url + "?design=" + name)
    wait.until(lambda d: js(d, "return state.sweep !== null && state.name === '%s' && "
                               "state.advice !== null" % name))
    time.sleep(0.3)


def type_into(d, id_, value):
    box = d.find_element(By.ID, id_)
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(Keys.DELETE)
    if value:
        box.send_keys(value)


opts = Options()
for arg in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
            "--window-size=1280,1700", "--hide-scrollbars"]:
    opts.add_argument(arg)
opts.binary_location = "/usr/bin/chromium"
opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})

with Server(tippe) as srv:
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
    try:
        wait = WebDriverWait(driver, 60)
        d = driver

        # ---- the headline says where the model does not hold -----------------------
        # drilled-ball-best: "3-in-1 and settable", but its launch checks stand on the
        # hole's rim at +z (tippe build: model_holds_at_poles false)
        open_design(d, wait, "drilled-ball-best")
        want = sheet("drilled-ball-best")
        holds = d.find_element(By.ID, "holds")
        check(want["model_holds_at_poles"] is False and holds.is_displayed() and
              "does not hold" in holds.text and "pole" in holds.text,
              "drilled-ball-best: tippe build says the model does not hold at the poles, the "
              "headline says '%s'" % holds.text)
        colours = js(d, "return [getComputedStyle(document.getElementById('holds')).backgroundColor,"
                        " getComputedStyle(document.getElementById('verdict')).color]")
        check(colours[0] != colours[1] and text(d, "verdict") == want["verdict"],
              "its own state and colour (%s) beside the verdict '%s' (%s)" %
              (colours[0], text(d, "verdict"), colours[1]))
        # the sheet's pole fixes, with their --set lines
        fixes = d.find_elements(By.CSS_SELECTOR, "#pole-fixes li")
        lines = [e.text for e in d.find_elements(By.CSS_SELECTOR, "#pole-fixes code.set-line")]
        want_lines = [" ".join("--set " + s for s in f["set"]) for f in want["pole_fixes"]]
        check(len(fixes) == len(want["pole_fixes"]) > 0 and lines == want_lines,
              "the sheet's %d pole fix(es) on the page with tippe build's --set lines: %s" %
              (len(want["pole_fixes"]), lines))
        # the launch checks as the sheet's table words them
        md = open(os.path.join(artefacts, "build-cli", "drilled-ball-best-build.md")).read()
        shown = [e.text for e in d.find_elements(By.CSS_SELECTOR, "#sheet-more li")]
        rim = [s for s in shown if "rim" in s and "(modelled)" in s and not s.startswith("Warning")]
        check(len(rim) == 2 and all(s.split(": ", 1)[1] in md for s in rim),
              "the sheet's launch checks on the rim, as its Markdown says them: %s" % rim)
        d.save_screenshot(os.path.join(artefacts, "page-1-holds.png"))
        # a fix tried on the form: the page's verdict is the one the sheet gave the fix
        fix = want["pole_fixes"][0]
        d.find_element(By.CSS_SELECTOR, "#pole-fixes button").click()
        wait.until(lambda d: js(d, "return state.verdict !== null && state.design.travel_mm[1]"
                                   " === %r" % json.loads(fix["set"][-1].split("=", 1)[1])[1]))
        check(text(d, "verdict") == fix["verdict"] and
              js(d, "return state.design.parts.find(p => p.name === 'hole').height_mm") ==
              float(fix["set"][0].split("=")[1]),
              "the fix tried on the form: the page says '%s', the sheet's fix '%s'" %
              (text(d, "verdict"), fix["verdict"]))

        # a design where the model holds everywhere on its travel: no such state
        open_design(d, wait, "shell-rod-best")
        ok = sheet("shell-rod-best")["model_holds_at_poles"]
        check(ok and not d.find_element(By.ID, "holds").is_displayed(),
              "shell-rod-best: the model holds (tippe build), no 'does not hold' shown")

        # ---- the zone table's notes ---------------------------------------------------
        open_design(d, wait, "m12-setscrew-printed")
        txt = cli("sweep", "designs/m12-setscrew-printed.json", json_out=False)
        cli_notes = [line[55:].strip() for line in txt.split("\n\n")[1].splitlines()[1:]
                     if re.match(r"^(I|II|III|Ia|Ib|IIa|IIb|IIc)\s", line)]
        page_notes = [e.text for e in d.find_elements(By.CSS_SELECTOR, "#zones td.notes")]
        norm = lambda s: re.sub(r"\s+", " ", s).strip()
        check([norm(x) for x in page_notes] == [norm(x) for x in cli_notes] and
              any("MODEL INVALID" in x for x in page_notes) and
              any("side down" in x for x in page_notes),
              "m12-setscrew-printed: the two III rows carry tippe sweep's notes: %s" % page_notes)

        # ---- the launch line ----------------------------------------------------------
        open_design(d, wait, "drilled-ball-best")
        type_into(d, "z2", "")
        d.find_element(By.ID, "check").click()
        time.sleep(0.5)
        out = d.find_element(By.ID, "check-result")
        check("Z2" in out.text and out.get_attribute("data-verdict") is None,
              "an empty Z2 box is refused, not run at 0: '%s'" % out.text)
        type_into(d, "z2", "8.95")
        type_into(d, "spin", "")
        d.find_element(By.ID, "check").click()
        time.sleep(0.5)
        check("spin" in out.text and out.get_attribute("data-verdict") is None,
              "an empty spin box is refused: '%s'" % out.text)
        type_into(d, "spin", "8.59")
        d.find_element(By.ID, "check").click()
        wait.until(lambda d: d.find_element(By.ID, "check-result").get_attribute("data-verdict"))
        line = text(d, "check-line")
        cmd = cli("check", "designs/drilled-ball-best.json", "--z2", "8.95", "--spin",
                  "8.59rev/s", json_out=False)
        check(line.startswith("Z2 8.95 mm, 8.59 rev/s, viscous"),
              "the line starts with the Z2, spin and law it ran: '%s'" % line[:60])
        warn = [e.text for e in d.find_elements(By.CSS_SELECTOR, "#check-result .check-warning")]
        check("\nrim " in cmd and "+z" in cmd and
              any("on the rim (modelled)" in w and "+z" in w for w in warn),
              "the command's rim line is carried: %s" % warn)
        check("decided by trapped" not in line and "proved at t = " in line and
              "before the flip" in line,
              "the decision is said in words, with its time before the flip: '%s'" % line)
        check(" run" not in re.sub(r"\s+", " ", cmd.split("\nrim ")[1].split("\n")[0]),
              "tippe check's rim line no longer calls the decision time the run's length")
        d.save_screenshot(os.path.join(artefacts, "page-2-check.png"))
        Select(d.find_element(By.ID, "friction")).select_by_value("coulomb")
        time.sleep(0.3)
        check(out.text == "" and not d.find_elements(By.CSS_SELECTOR, "#theta-plot svg"),
              "a changed friction clears the old result and its plot")

        # ---- words ----------------------------------------------------------------------
        titles = [x["title"] for x in srv.request("GET", "/api/designs")[2]["designs"]]
        check(len(set(titles)) == len(titles), "no two shipped designs share a title (%d)" %
              len(titles))
        want_terms = ["A/C", "eps/R", "robust", "band", "trapped", "patch law"]
        Select(d.find_element(By.ID, "friction")).select_by_value("viscous")
        d.find_element(By.ID, "check").click()
        wait.until(lambda d: d.find_element(By.ID, "check-result").get_attribute("data-verdict"))
        found = js(d, "const out = {}; for (const e of document.querySelectorAll('[title]'))"
                      " { const t = e.getAttribute('title'); const w = t.split(':')[0];"
                      " if (t.length > w.length + 20) out[w] = t; } return out;")
        check(all(w in found for w in want_terms),
              "every term has a one-line explanation on hover: %s" %
              [w for w in want_terms if w not in found])
        # the legend's keys are drawn with the bar's own fills
        bar = js(d, "const r = [...document.querySelectorAll('#zonebar rect')].find(r =>"
                    " r.getAttribute('opacity') === '0.28'); return r ? [r.getAttribute('fill'),"
                    " r.getAttribute('opacity')] : null")
        key = js(d, "const r = document.querySelector('#legend [data-key=band]'); return "
                    "[r.getAttribute('fill'), r.getAttribute('opacity')]")
        groups = js(d, "return [...document.querySelectorAll('#legend [data-key=group]')]"
                       ".map(r => r.getAttribute('fill'))")
        bar_groups = js(d, "return [...document.querySelectorAll('#zonebar rect')]"
                           ".map(r => r.getAttribute('fill'))")
        check(bar is not None and bar == key and all(g in bar_groups for g in groups[:2]),
              "the legend's band key is the bar's band (%s, %s) and its group colours the "
              "bar's" % (key, bar))
        # the infill as PrusaSlicer users type it
        open_design(d, wait, "m12-setscrew-printed")
        type_into(d, "f-parts_0__print_infill", "20%")
        want = sheet("m12-setscrew-printed", "parts.body.print.infill=0.2")["verdict"]
        wait.until(lambda d: js(d, "return state.verdict !== null && "
                                   "state.design.parts[0].print.infill === 0.2"))
        check(text(d, "verdict") == want, "infill '20%%' is 0.2: the page says '%s', tippe "
              "build --set parts.body.print.infill=0.2 '%s'" % (text(d, "verdict"), want))
        d.save_screenshot(os.path.join(artefacts, "page-3-words.png"))

        logs = [e for e in d.get_log("browser") if e["level"] in ("SEVERE", "WARNING")]
        check(not logs, "no console errors%s" %
              ("" if not logs else ": " + "; ".join(e["message"][:120] for e in logs[:3])))
    finally:
        driver.quit()

print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
