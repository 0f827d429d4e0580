#!/usr/bin/env bash
# The figures of docs/optimise.md, "Defaults against a 10x longer search": runs tippe
# optimise on SPEC with its "search" replaced by the default search made SCALE times
# longer (DIRECT-L 1500 SCALE + COBYLA 1000 SCALE evaluations per choice; SCALE 1: the
# defaults), and writes its --json to OUT.
# Usage, from the repository root: tools/optimise_10x.sh SPEC.json OUT.json [SCALE]
# (default SCALE 10; TIPPE=path/to/tippe to use another build than build/tippe).
set -eu
spec=${1:?usage: tools/optimise_10x.sh SPEC.json OUT.json [SCALE]}
out=${2:?usage: tools/optimise_10x.sh SPEC.json OUT.json [SCALE]}
scale=${3:-10}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$spec" "$tmp/spec.json" "$scale" <<'PY'
import json, os, sys
spec, out, scale = sys.argv[1], sys.argv[2], int(sys.argv[3])
d = json.load(open(spec))
base = os.path.dirname(os.path.abspath(spec))
d["design"] = os.path.join(base, d["design"])
if "catalogue" in d:
    d["catalogue"] = os.path.join(base, d["catalogue"])
d["search"] = {"algorithm": "DIRECT-L", "evaluations": 1500 * scale, "polish": "COBYLA",
               "polish_evaluations": 1000 * scale}
json.dump(d, open(out, "w"), indent=1)
PY
mkdir -p "$(dirname "$out")"
"${TIPPE:-build/tippe}" optimise "$tmp/spec.json" --json --threads 2 >"$out.part"
mv "$out.part" "$out"
python3 - "$out" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
ok = [c for c in o["choices"] if c["status"] == "ok"]
best = max(ok, key=lambda c: c["narrowest_zone_mm"]) if ok else None
print("%d candidates; widest narrowest zone %s" % (o["evaluations"],
      "%.9f mm (%s)" % (best["narrowest_zone_mm"], best["choice"]) if best else "none"))
PY
