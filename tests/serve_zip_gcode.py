#!/usr/bin/env python3
"""A build zip of a design with an uploaded G-code (issue 37): the zip carries the G-code
itself beside the design, which names it by a path relative to the design file, so that
`unzip; tippe build STEM.json` gives the page's verdict. The G-code is PrusaSlicer's of the
printed M12 (tippe slice); the server reads it from the upload, never from a path.

Usage: serve_zip_gcode.py TIPPE WORKDIR. Prints 'N passed, M failed'."""
import io
import json
import os
import shutil
import subprocess
import sys
import zipfile

from serve_lib import Server, REPO, GCODE_WIDTH_TOL_MM, same_verdict, check, finish

tippe, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


# PrusaSlicer's G-code of the printed M12 at 25 % infill (the design's body): not 3-in-1 (its
# G-code placed where the part as made stands: docs/printing.md), so the sheet tries changes
design = json.load(open(os.path.join(REPO, "designs", "m12-setscrew-printed.json")))
design["parts"][0]["print"] = {"infill": 0.25}
src = os.path.join(work, "m12-25.json")
json.dump(dict(design, materials=os.path.join(REPO, "designs", "materials.json")),
          open(src, "w"), indent=1)
subprocess.run([tippe, "slice", src, "-o", os.path.join(work, "sliced")], cwd=REPO,
               capture_output=True, check=True)
gcode = open(os.path.join(work, "sliced", "m12-25.gcode"), "rb").read()

# a build of a design with a G-code takes tippe build's time (20 s on one core here: its
# launch checks and each change it tries): the budget is raised so that a loaded machine
# does not turn it into a 503
with Server(tippe, "--budget", "600") as srv:
    st, _, up = srv.post("/api/gcode?name=m12-25.gcode", gcode,
                         headers={"Content-Type": "text/x-gcode"})
    check(st == 200 and up["gcode"].startswith("upload:"),
          "the G-code uploaded (%d bytes): %s" % (len(gcode), up.get("gcode", up)))
    design["parts"][0]["print"]["gcode"] = up["gcode"]
    st, _, page = srv.post("/api/verdict", {"design": design})
    check(st == 200, "the page's verdict of the design with the upload: %s" % page.get("verdict"))
    st, hdrs, z = srv.post("/api/build", {"design": design, "name": "m12-upload"}, raw=True,
                           timeout=900)
    check(st == 200 and hdrs.get("content-type") == "application/zip",
          "the build zip (HTTP %d, %d bytes)" % (st, len(z)))
zf = zipfile.ZipFile(io.BytesIO(z))
names = zf.namelist()
check("m12-upload.json" in names and "m12-upload-body.gcode" in names,
      "the zip holds the design and its G-code beside it: %s" %
      [n for n in names if n.endswith((".json", ".gcode"))])
zipped = json.loads(zf.read("m12-upload.json")) if "m12-upload.json" in names else {}
gref = zipped.get("parts", [{}])[0].get("print", {}).get("gcode")
check(gref == "m12-upload-body.gcode" and "upload:" not in json.dumps(zipped),
      "the zip's design names its G-code by a path relative to it: %s" % gref)
check("m12-upload-body.gcode" in names and zf.read("m12-upload-body.gcode") == gcode,
      "the zip's G-code is the uploaded file byte for byte")
built = json.loads(zf.read("m12-upload-build.json"))
# A sheet that is settable as it stands tries no change (the as-made part, issue 40,
# made this G-code's M12 settable); one that tries changes says they keep the slicing.
if built["changes_tried"] > 0:
    check(any("is printed as its G-code deposits it" in n for n in built["notes"]),
          "the sheet says the changes it tried keep the G-code's slicing (no infill step: %d "
          "changes tried)" % built["changes_tried"])
else:
    check(built["verdict"] == "3-in-1 and settable" and not built.get("to_make_it_settable"),
          "the sheet tried no change, and needs none: %s" % built["verdict"])
cannot = [f["fix"] for f in built["pole_fixes"] if f["verdict"] == "failed"]
check(cannot and all("slice the fixed design and give its G-code" in f for f in cannot),
      "the poles' fixes it cannot try (the G-code is of the part without them) say to slice "
      "the fixed design: %d of %d" % (len(cannot), len(built["pole_fixes"])))
md = [n for n in names if n.endswith("-build.md")]
check(md and "upload:" not in zf.read(md[0]).decode(),
      "the zip's sheet names no upload id")

# a sheet that must try changes on a G-code part (a travel too short for its zones)
# tries no infill step and says why
if "m12-upload.json" in names:
    zf.extractall(os.path.join(work, "short"))
    r = subprocess.run([tippe, "build", "m12-upload.json", "-o", "cli", "--no-export", "--json",
                        "--set", "travel_mm=[0,3]"], cwd=os.path.join(work, "short"),
                       capture_output=True, text=True)
    short = json.loads(r.stdout) if r.returncode == 0 else {}
    check(short.get("changes_tried", 0) > 0 and
          any("is printed as its G-code deposits it" in n for n in short.get("notes", [])),
          "with 3 mm of travel the sheet tries %d changes and says they keep the G-code's "
          "slicing" % short.get("changes_tried", 0))

# unzipped anywhere: the command builds the design as the page judged it
unz = os.path.join(work, "unzipped")
zf.extractall(unz)
r = subprocess.run([tippe, "build", "m12-upload.json", "-o", "cli", "--no-export", "--json"],
                   cwd=unz, capture_output=True, text=True)
check(r.returncode == 0, "tippe build m12-upload.json in the unzipped folder runs%s" %
      ("" if r.returncode == 0 else ": " + r.stderr.strip()[:300]))
if r.returncode == 0:
    sheet = json.loads(r.stdout)
    check(not same_verdict(page, sheet, GCODE_WIDTH_TOL_MM),
          "its verdict is the page's: %s (robust widths %s mm)" %
          (sheet["verdict"], ", ".join("%.4f" % s.get("robust_width_mm", 0)
                                      for s in sheet["settings"])))
finish()
