#!/usr/bin/env python3
"""Independent readers for tippe export's files, used by tests/test_export_cli.sh.

  export_check.py stl FILE           numpy-stl: topology, volume, bounding box
  export_check.py 3mf FILE           zipfile + XML: objects, their volumes
  export_check.py svg FILE           the drawing's dimension labels
  export_check.py export REPORT.json every file of a tippe export --json report
  export_check.py exact DESIGN.json  closed-form volumes of the printed body of
                                     the simple shipped designs (ball less a
                                     through hole; shell), from the JSON alone

Each prints one JSON object on stdout. Nothing here calls tippe's code."""
import json
import math
import re
import sys
import xml.etree.ElementTree as ET
import zipfile

import warnings

import numpy as np

warnings.simplefilter("ignore")


def topology(tri_vertices):
    """tri_vertices: (n, 3, 3) float32. Vertices are merged by exact position
    (as a slicer does); returns edge counts and signed volume."""
    flat = tri_vertices.reshape(-1, 3)
    _, index = np.unique(flat, axis=0, return_inverse=True)
    tri = index.reshape(-1, 3)
    degenerate = int(np.sum((tri[:, 0] == tri[:, 1]) | (tri[:, 1] == tri[:, 2]) |
                            (tri[:, 0] == tri[:, 2])))
    a, b, c = (tri_vertices[:, k, :].astype(np.float64) for k in range(3))
    area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    degenerate += int(np.sum(area2 == 0)) - int(np.sum((area2 == 0) & (
        (tri[:, 0] == tri[:, 1]) | (tri[:, 1] == tri[:, 2]) | (tri[:, 0] == tri[:, 2]))))
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    und = np.sort(directed, axis=1)
    _, counts = np.unique(und, axis=0, return_counts=True)
    _, dcounts = np.unique(directed, axis=0, return_counts=True)
    volume = float(np.sum(np.einsum("ij,ij->i", a, np.cross(b, c))) / 6)
    return {
        "triangles": int(len(tri)),
        "open_edges": int(np.sum(counts == 1)),
        "nonmanifold_edges": int(np.sum(counts > 2)),
        # a directed edge used twice: two neighbours disagree on the normal
        "inconsistent_edges": int(np.sum(dcounts > 1)),
        "degenerate_facets": degenerate,
        "volume_mm3": volume,
        "min": [float(v) for v in flat.min(axis=0)],
        "max": [float(v) for v in flat.max(axis=0)],
    }


def check_stl(path):
    from stl import mesh  # numpy-stl (Debian python3-stl)
    m = mesh.Mesh.from_file(path)
    out = topology(m.vectors.astype(np.float32))
    # stored normals must point the way the vertex order says (outward)
    computed = np.cross(m.vectors[:, 1] - m.vectors[:, 0], m.vectors[:, 2] - m.vectors[:, 0])
    out["normals_disagreeing"] = int(np.sum(np.einsum("ij,ij->i", computed, m.normals) <= 0))
    vol, _, _ = m.get_mass_properties()
    out["numpy_stl_volume_mm3"] = float(vol)
    return out


def check_3mf(path):
    ns = {"m": "http://schemas.microsoft.com/3dmanufacturing/core/2015/02"}
    with zipfile.ZipFile(path) as z:
        names = z.namelist()
        model = [n for n in names if n.endswith(".model")]
        root = ET.fromstring(z.read(model[0]))
    unit = root.get("unit", "millimeter")
    objects = []
    for obj in root.iter("{%s}object" % ns["m"]):
        verts = np.array([[float(v.get(k)) for k in "xyz"]
                          for v in obj.iter("{%s}vertex" % ns["m"])], dtype=np.float32)
        tris = np.array([[int(t.get(k)) for k in ("v1", "v2", "v3")]
                         for t in obj.iter("{%s}triangle" % ns["m"])])
        info = topology(verts[tris])
        info["name"] = obj.get("name")
        objects.append(info)
    items = len(list(root.iter("{%s}item" % ns["m"])))
    return {"unit": unit, "objects": objects, "build_items": items, "parts": names}


def check_svg(path):
    root = ET.parse(path).getroot()
    dims = []
    for t in root.iter("{http://www.w3.org/2000/svg}text"):
        if t.get("class") != "dim":
            continue
        text = "".join(t.itertext())
        numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", text)]
        dims.append({"name": t.get("data-name"), "mm": float(t.get("data-mm")),
                     "text": text, "numbers": numbers})
    return {"dims": dims}


def exact(path):
    """Printed volume of a ball with an axial through hole (clearance c) or of
    a plain shell, from the design file alone."""
    d = json.load(open(path))
    R = d["radius_mm"]
    parts = {p["name"]: p for p in d["parts"]}
    out = {"radius_mm": R}
    for p in d["parts"]:
        if p.get("shape") == "shell" and not p.get("void"):
            ri = p.get("radius_mm", R) - p["thickness_mm"]
            out["shell_mm3"] = 4 / 3 * math.pi * (p.get("radius_mm", R) ** 3 - ri ** 3)
        if p.get("void") and p.get("clip") == "sphere" and "height_mm" not in p \
                and parts[p["cut_from"]]["shape"] == "ball":
            out["hole_radius_mm"] = p["radius_mm"]
    return out


def check_export(report_path):
    """Every STL and the 3MF named by tippe export's --json report, against the
    report: clean topology, volume within 0.1 % of the body's exact volume
    (the issue's bound; the default chord gives <= 8.5e-4 on the shipped
    designs), bounding box as reported, same bodies and volumes in the 3MF.
    Returns the list of failures."""
    r = json.load(open(report_path))
    fails = []
    for b in r["bodies"]:
        s = check_stl(b["stl"])
        if s["open_edges"] or s["nonmanifold_edges"] or s["inconsistent_edges"] \
                or s["degenerate_facets"] or s["normals_disagreeing"]:
            fails.append(f"{b['stl']}: topology {s}")
        exact = b["exact_volume_mm3"]
        if exact is None or abs(s["volume_mm3"] - exact) > 1e-3 * exact:
            fails.append(f"{b['stl']}: volume {s['volume_mm3']} vs exact {exact}")
        if abs(s["numpy_stl_volume_mm3"] - s["volume_mm3"]) > 1e-6 * s["volume_mm3"]:
            fails.append(f"{b['stl']}: numpy-stl's volume {s['numpy_stl_volume_mm3']}")
        for k in range(3):  # float32 rounding of the coordinates
            if abs(s["min"][k] - b["bbox_min_mm"][k]) > 1e-4 or \
                    abs(s["max"][k] - b["bbox_max_mm"][k]) > 1e-4:
                fails.append(f"{b['stl']}: bounding box {s['min']} {s['max']}")
    threemf = [f for f in r["files"] if f.endswith(".3mf")]
    if threemf:
        m = check_3mf(threemf[0])
        objs = {o["name"]: o for o in m["objects"]}
        if m["unit"] != "millimeter" or not (len(objs) == len(r["bodies"]) == m["build_items"]):
            fails.append(f"3MF: unit {m['unit']}, {len(objs)} objects, {m['build_items']} items")
        for b in r["bodies"]:
            o = objs.get(b["name"])
            if o is None or o["open_edges"] or o["inconsistent_edges"] or o["degenerate_facets"] \
                    or abs(o["volume_mm3"] - b["mesh_volume_mm3"]) > 1e-6 * b["mesh_volume_mm3"]:
                fails.append(f"3MF body {b['name']}: {o}")
    return {"failures": fails, "bodies": len(r["bodies"])}


def main():
    kind, path = sys.argv[1], sys.argv[2]
    result = {"stl": check_stl, "3mf": check_3mf, "svg": check_svg, "exact": exact,
              "export": check_export}[kind](path)
    json.dump(result, sys.stdout)
    print()


if __name__ == "__main__":
    main()
