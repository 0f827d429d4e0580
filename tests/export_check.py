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
        "area_mm2": stl_area(tri_vertices.astype(np.float64)),
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
    report: clean topology, volume within chord x area of the body's exact
    volume, bounding box as reported, same bodies and volumes in the 3MF.
    The volume bound: every facet lies within the chord c of the true surface
    (what --chord-mm promises; `chord` below measures it), so the region
    between mesh and body is at most c thick over the surface, and its volume
    is at most c x the surface area. The area is the mesh's: it is the true
    surface's to O(c / r) (3e-4 low on the shipped shells at c = 0.01 mm), far
    inside the bound's own margin: the mean sag of a chord is 2/3 of its
    largest, so the error is about half the bound on the drilled balls (0.47
    at c = 0.01 mm) and less on the shells, whose inner wall errs the other
    way (0.17). A fixed relative tolerance is no bound: a thin shell has four
    times the surface of a solid ball of its volume.
    Returns the list of failures."""
    r = json.load(open(report_path))
    fails = []
    for b in r["bodies"]:
        s = check_stl(b["stl"])
        if s["open_edges"] or s["nonmanifold_edges"] or s["inconsistent_edges"] \
                or s["degenerate_facets"] or s["normals_disagreeing"]:
            fails.append(f"{b['stl']}: topology {s}")
        exact = b["exact_volume_mm3"]
        if exact is None or abs(s["volume_mm3"] - exact) > r["chord_mm"] * s["area_mm2"]:
            fails.append(f"{b['stl']}: volume {s['volume_mm3']} vs exact {exact}, more than "
                         f"chord x area = {r['chord_mm'] * s['area_mm2']} apart")
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


def stl_area(v):
    """Surface area of triangles v (n, 3, 3), mm^2."""
    return float(np.sum(np.linalg.norm(np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), axis=1)) / 2)


def design_region(d, printed, grown, clearance):
    """The printed region of design d in the (r, z) half-plane, from the JSON
    alone: inside(r, z) (numpy arrays) and every curve its boundary can lie on,
    as parametrised point samplers. printed: names of the printed parts; grown:
    names of the holes grown radially by clearance (tippe export's report)."""
    R = d["radius_mm"]
    parts = d["parts"]
    shells = [p for p in parts if p["shape"] == "shell" and not p.get("moving") and not p.get("void")]
    curves = []   # (kind, params)

    def ball(rho, z0):
        curves.append(("circle", (rho, z0)))
        return lambda r, z: r * r + (z - z0) ** 2 <= rho * rho

    def clip_of(p):
        if "clip" not in p:
            return None
        if p["clip"] == "sphere":
            return ball(R, 0)
        s = shells[0]
        ro = s.get("radius_mm", R)
        ri = ro - s["thickness_mm"]
        if p["clip"] == "cavity":
            return ball(ri, 0)
        outer, inner = ball(ro, 0), ball(ri, 0)
        return lambda r, z: outer(r, z) & ~inner(r, z)

    def solid(p, g):
        z0 = p.get("z_mm", 0.0)
        sh = p["shape"]
        if sh == "ball":
            f = ball(p.get("radius_mm", R) + g, z0)
        elif sh == "shell":
            ro = p.get("radius_mm", R) + g
            ri = p.get("radius_mm", R) - p["thickness_mm"] - g
            outer, inner = ball(ro, z0), ball(ri, z0) if ri > 0 else (lambda r, z: r < 0)
            f = lambda r, z: outer(r, z) & ~inner(r, z)
        elif sh in ("cylinder", "tube"):
            ro = p["radius_mm"] + g
            ri = max(0.0, p.get("inner_radius_mm", 0) - g) if p.get("inner_radius_mm", 0) > 0 else 0.0
            h = p.get("height_mm", 4 * R)
            curves.append(("vline", (ro, z0 - h / 2, z0 + h / 2)))
            if ri > 0:
                curves.append(("vline", (ri, z0 - h / 2, z0 + h / 2)))
            for zz in (z0 - h / 2, z0 + h / 2):
                curves.append(("hline", (ri, ro, zz)))
            f = lambda r, z: (r <= ro) & (r >= ri) & (np.abs(z - z0) <= h / 2)
        else:  # torus: an ellipse revolved
            c, a, b = p["centre_radius_mm"], p["radial_semi_mm"] + g, p["axial_semi_mm"] + g
            curves.append(("ellipse", (c, a, b, z0)))
            f = lambda r, z: ((r - c) / a) ** 2 + ((z - z0) / b) ** 2 <= 1
        clip = clip_of(p)
        return f if clip is None else (lambda r, z: f(r, z) & clip(r, z))

    solids = [solid(p, 0.0) for p in parts if p["name"] in printed and not p.get("void")]
    holes = [solid(p, clearance if p["name"] in grown else 0.0) for p in parts
             if p.get("void") and p.get("cut_from") in printed]

    def inside(r, z):
        r = np.abs(r)  # a solid of revolution: the axis is no surface
        a = np.zeros(np.shape(r), dtype=bool)
        for f in solids:
            a |= f(r, z)
        for f in holes:
            a &= ~f(r, z)
        return a

    return inside, curves


def curve_samples(kind, q, step, rmax):
    if kind == "circle":
        rho, z0 = q
        t = np.linspace(-math.pi / 2, math.pi / 2, max(3, int(math.pi * rho / step) + 1))
        return np.c_[rho * np.cos(t), z0 + rho * np.sin(t)]
    if kind == "ellipse":
        c, a, b, z0 = q
        t = np.linspace(0, 2 * math.pi, max(5, int(2 * math.pi * max(a, b) / step) + 1))
        return np.c_[c + a * np.cos(t), z0 + b * np.sin(t)]
    if kind == "vline":
        r0, z0, z1 = q
        z0, z1 = max(z0, -rmax), min(z1, rmax)
        z = np.linspace(z0, z1, max(2, int((z1 - z0) / step) + 1))
        return np.c_[np.full_like(z, r0), z]
    r0, r1, z0 = q
    r = np.linspace(r0, r1, max(2, int((r1 - r0) / step) + 1))
    return np.c_[r, np.full_like(r, z0)]


def check_chord(report_path):
    """How far tippe export's meshes stray from the true surface (the chord the
    report promises), from the design file alone. For a solid of revolution
    the 3-D distance of a point from the surface is the distance of its
    (r, z) from the region's boundary curve in the half-plane. The boundary
    is sampled every STEP mm along each curve it can lie on (a sample is on
    it when points 1e-7 mm either side are one in, one out of the region);
    distances to the samples overstate the true ones by at most STEP / 2.
    forward: mesh vertices, edge midpoints and facet centroids to the true
    surface; reverse: the true surface to the mesh (its cross-section midway
    between two angle steps, where it is farthest inside: the profile polygon
    with r scaled by cos(pi / n)). Unsplit bodies only (a split half is moved)."""
    from scipy.spatial import cKDTree
    from stl import mesh
    STEP = 5e-4
    r = json.load(open(report_path))
    d = json.load(open(r["file"]))
    out = {"chord_mm": r["chord_mm"], "sample_step_mm": STEP, "bodies": []}
    for b in r["bodies"]:
        if "-lower" in b["name"] or "-upper" in b["name"] or b["name"].startswith("joint-ring"):
            continue
        inside, curves = design_region(d, set(b["name"].split("+")), set(r["holes_with_clearance"]),
                                       r["clearance_mm"])
        pts = np.concatenate([curve_samples(k, q, STEP, d["radius_mm"] + 5) for k, q in curves])
        pts = pts[pts[:, 0] >= 0]
        e = 1e-7
        near = np.stack([inside(pts[:, 0] + dr, pts[:, 1] + dz)
                         for dr, dz in ((e, 0), (-e, 0), (0, e), (0, -e), (e, e), (-e, -e), (e, -e), (-e, e))])
        boundary = pts[near.any(axis=0) & ~near.all(axis=0)]
        tree = cKDTree(boundary)
        m = mesh.Mesh.from_file(b["stl"])
        v = m.vectors.astype(np.float64)
        probe = np.concatenate([v.reshape(-1, 3), (v + np.roll(v, 1, axis=1)).reshape(-1, 3) / 2,
                                v.mean(axis=1)])
        fwd, _ = tree.query(np.c_[np.hypot(probe[:, 0], probe[:, 1]), probe[:, 2]])
        # the profile polygon: edges between vertices in the half-plane y = 0, x >= 0
        n = b["angle_steps"]
        seg = []
        for i, j in ((0, 1), (1, 2), (2, 0)):
            a, c = v[:, i], v[:, j]
            on = (a[:, 1] == 0) & (c[:, 1] == 0) & (a[:, 0] >= 0) & (c[:, 0] >= 0)
            seg.append(np.c_[a[on][:, [0, 2]], c[on][:, [0, 2]]])
        seg = np.unique(np.concatenate(seg), axis=0)
        seg[:, [0, 2]] *= math.cos(math.pi / n)
        length = np.hypot(seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1])
        k = np.maximum(2, np.ceil(length / STEP).astype(int) + 1)
        t = np.concatenate([np.linspace(0, 1, kk) for kk in k])
        s0 = np.repeat(seg, k, axis=0)
        mid = np.c_[s0[:, 0] + t * (s0[:, 2] - s0[:, 0]), s0[:, 1] + t * (s0[:, 3] - s0[:, 1])]
        rev, _ = cKDTree(mid).query(boundary)
        out["bodies"].append({"name": b["name"], "angle_steps": n,
                              "boundary_samples": int(len(boundary)),
                              "forward_max_mm": float(fwd.max()),
                              "reverse_max_mm": float(rev.max()),
                              "mesh_area_mm2": stl_area(v)})
    return out


def main():
    kind, path = sys.argv[1], sys.argv[2]
    result = {"stl": check_stl, "3mf": check_3mf, "svg": check_svg, "exact": exact,
              "export": check_export, "chord": check_chord}[kind](path)
    json.dump(result, sys.stdout)
    print()


if __name__ == "__main__":
    main()
