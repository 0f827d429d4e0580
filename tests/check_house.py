#!/usr/bin/env python3
"""The house's rules, checked from the compiler's objects and the sources
(docs/architecture.md):

1. names: every symbol libtippe.a exports starts with tippe_ and a name its folder
   owns (a misspelt or foreign module prefix is a leak between modules);
2. layers: a folder includes public headers (tippe/NAME.h) only of modules on
   its own layer or below, and internal headers only of its own folder (and
   base's JSON reader, the plumbing of every loader);
3. no cycles: file A calls file B when an undefined symbol of A.o is defined by
   B.o (nm); the calls between the library's and the command's files form no
   circle, and a call between folders never runs up a layer;
6. friction laws: no .c file outside src/physics/ names a law (TIPPE_FRICTION_*):
   a law is one entry of src/physics/friction_laws.c's table;
7. paths: no .c file but src/base/path.c splits a path at its last '/' by hand.

Usage: check_house.py SOURCE_DIR BUILD_DIR. Prints one line per breach and the
closing line 'N passed, M failed'."""
import os
import re
import subprocess
import sys

src_root, build = sys.argv[1], sys.argv[2]

# Bottom up; a folder may use its own layer and those below.
LAYER = {"base": 0, "print": 1, "theory": 1, "design": 2, "physics": 2, "launch": 3,
         "profile": 3, "scenario": 4, "sweep": 4, "optimise": 5, "build": 5, "plot": 6,
         "export": 6, "animate": 6, "cli": 7, "modules": 7, "serve": 7}
# top.h is a header alone (the struct design.h fills and physics takes), on base's layer.
HEADER_LAYER = {"base": 0, "top": 0, "print": 1, "theory": 1, "design": 2, "physics": 2,
                "launch": 3, "profile": 3, "scenario": 4, "sweep": 4, "optimise": 5, "build": 5,
                "plot": 6, "export": 6, "animate": 6, "serve": 7}
# The modules a folder may use on its own layer (the top CMakeLists.txt's TIPPE_*_USES and
# the front ends): any other two folders of one layer are siblings that know nothing of each
# other (physics and theory know no design file and no printed part; issue 34.4).
SIBLING_USES = {"optimise": {"build"}, "cli": {"serve"}, "modules": {"serve"}}
# The names each folder's objects may export (after tippe_).
OWNS = {
    "base": ["error", "gsl", "report", "progress", "json", "file", "cancel", "path"],
    "print": ["print", "gcode", "moments", "ball", "shell", "tube", "torus"],
    "design": ["design", "tolerance", "tolerances", "materials"],
    "theory": ["theory", "group", "final"],
    "physics": ["dynamics", "verdict", "decision", "friction", "contact"],
    "launch": ["launch", "friction"],
    "profile": ["profile"],
    "scenario": ["scenario"],
    "sweep": ["sweep"],
    "optimise": ["optimise"],
    "build": ["build"],
    "plot": ["plot", "sweep_plot", "launch_plot", "optimise_plot"],
    "export": ["export", "mesh", "drawing", "scad", "slice"],
    "animate": ["animate", "film", "scene", "encode"],
    "serve": ["serve"],
}

failures, checks = [], 0


def fail(msg):
    failures.append(msg)
    print("FAIL " + msg)


def objects():
    """(folder, file, path of .o) of the library's and the command's objects."""
    out = []
    for d, _, files in os.walk(build):
        if "/tests" in d[len(build):] or "/tools" in d[len(build):]:
            continue
        for f in files:
            if not f.endswith(".c.o"):
                continue
            m = re.search(r"/src/([a-z_]+)/([a-z_0-9]+\.c)\.o$", os.path.join(d, f))
            source = os.path.join(src_root, "src", m.group(1), m.group(2)) if m else ""
            if m and os.path.exists(source) and "tippe-mpi.dir" not in d \
                    and "_module.dir" not in d:
                out.append((m.group(1), m.group(2), os.path.join(d, f)))
    return out


objs = objects()
if len(objs) < 40:
    sys.exit("check_house: found only %d objects under %s (build it first)" % (len(objs), build))

# 1. names
for folder, name, path in objs:
    if folder in ("cli", "modules"):
        continue
    text = subprocess.run(["nm", "-g", "--defined-only", path], capture_output=True,
                          text=True).stdout
    for line in text.splitlines():
        parts = line.split()
        if len(parts) < 3:
            continue
        sym = parts[2]
        checks += 1
        if sym.startswith(".gomp_critical_user_tippe_"):
            continue  # an OpenMP named critical section: tippe_ by its name
        if sym.startswith(("__odr_asan", "__asan_", "__ubsan_", "__sancov_")):
            continue  # a sanitizer's own symbol (TIPPE_SANITIZE, TIPPE_FUZZ builds)
        if not sym.startswith("tippe_"):
            fail("names: src/%s/%s exports %s (no tippe_ prefix)" % (folder, name, sym))
        elif not any(sym[6:] == own or sym[6:].startswith(own + "_") for own in OWNS[folder]):
            fail("names: src/%s/%s exports %s (not a name of %s: %s)" %
                 (folder, name, sym, folder, ", ".join(OWNS[folder])))

# 2. layers, by the includes of every source and internal header
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
for folder in sorted(os.listdir(os.path.join(src_root, "src"))):
    fdir = os.path.join(src_root, "src", folder)
    if not os.path.isdir(fdir):
        continue
    for f in sorted(os.listdir(fdir)):
        if not f.endswith((".c", ".h")):
            continue
        text = open(os.path.join(fdir, f), encoding="utf-8").read()
        for inc in INCLUDE.findall(text):
            checks += 1
            where = "src/%s/%s includes \"%s\"" % (folder, f, inc)
            m = re.match(r"tippe/([a-z_]+)\.h$", inc)
            if m:
                mod = m.group(1)
                if mod not in HEADER_LAYER:
                    fail("layers: %s: no such module" % where)
                elif HEADER_LAYER[mod] > LAYER[folder]:
                    fail("layers: %s: %s (layer %d) is above %s (layer %d)" %
                         (where, mod, HEADER_LAYER[mod], folder, LAYER[folder]))
                elif HEADER_LAYER[mod] == LAYER[folder] and mod not in (folder, "top") and \
                        mod not in SIBLING_USES.get(folder, ()):
                    fail("layers: %s: %s is a sibling of %s on layer %d (not in SIBLING_USES)" %
                         (where, mod, folder, LAYER[folder]))
                continue
            m = re.match(r"(?:\.\./)?([a-z_]+)/[a-z_]+\.h$", inc)
            if m:
                other = m.group(1)
                if other != folder and inc != "base/json.h" and \
                        not (folder == "cli" and other == "modules"):
                    fail("layers: %s: another module's internal header" % where)

# 3. calls between files
defined, undefined = {}, {}
for folder, name, path in objs:
    if folder == "modules":
        continue  # the command's stubs define the heavy modules' names again
    key = "src/%s/%s" % (folder, name)
    text = subprocess.run(["nm", path], capture_output=True, text=True).stdout
    d, u = set(), set()
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[0] == "U":
            u.add(parts[1])
        elif len(parts) == 3 and parts[1] in "TDBRC":
            d.add(parts[2])
    defined[key], undefined[key] = d, u
owner = {}
for key, syms in defined.items():
    for s in syms:
        owner.setdefault(s, key)
edges = {k: set() for k in defined}
why = {}
for key, syms in undefined.items():
    for s in syms:
        if s in owner and owner[s] != key:
            edges[key].add(owner[s])
            why.setdefault((key, owner[s]), []).append(s)
for a, bs in sorted(edges.items()):
    for b in sorted(bs):
        checks += 1
        fa, fb = a.split("/")[1], b.split("/")[1]
        if LAYER[fb] > LAYER[fa]:
            fail("layers: %s calls %s, a layer up (%s)" % (a, b, ", ".join(sorted(why[(a, b)])[:4])))
        elif LAYER[fb] == LAYER[fa] and fb != fa and fb not in SIBLING_USES.get(fa, ()):
            fail("layers: %s calls %s, a sibling on its layer (%s)" %
                 (a, b, ", ".join(sorted(why[(a, b)])[:4])))

# Tarjan's strongly connected components: any with two files or more is a cycle.
index, low, stack, on, comps, counter = {}, {}, [], set(), [], [0]
sys.setrecursionlimit(10000)


def strong(v):
    index[v] = low[v] = counter[0]
    counter[0] += 1
    stack.append(v)
    on.add(v)
    for w in edges[v]:
        if w not in index:
            strong(w)
            low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop()
            on.discard(w)
            comp.append(w)
            if w == v:
                break
        comps.append(comp)


for v in sorted(edges):
    if v not in index:
        strong(v)
checks += 1
for comp in comps:
    if len(comp) > 1:
        ties = ["%s -> %s: %s" % (a, b, ", ".join(sorted(why[(a, b)])[:4]))
                for a in sorted(comp) for b in sorted(edges[a]) if b in comp]
        fail("cycle: %s call each other around (%s)" % (", ".join(sorted(comp)), "; ".join(ties)))

# 4. the places docs/architecture.md gives a new thing ("Where a new thing goes")
def read(rel):
    return open(os.path.join(src_root, rel), encoding="utf-8").read()


def calls(a, b):
    return b in edges.get(a, set())


# A verb: its line in verbs.c, its file (VERB_verb.c when a module has its name), its
# prototype in cli.h.
cli_h = read("src/cli/cli.h")
verbs = re.findall(r'\{"([a-z]+)", (tippe_cli_[a-z_]+),', read("src/cli/verbs.c"))
checks += 1
if len(verbs) < 10:
    fail("verbs: src/cli/verbs.c: found only %d verbs (its table changed shape?)" % len(verbs))
for verb, fn in verbs:
    checks += 1
    name = verb + ("_verb" if verb in HEADER_LAYER else "")
    key = "src/cli/%s.c" % name
    if fn not in defined.get(key, set()):
        fail("verbs: %s is in src/cli/verbs.c but %s does not define %s" % (verb, key, fn))
    if not re.search(r"\bint %s\(" % fn, cli_h):
        fail("verbs: %s has no prototype in src/cli/cli.h" % fn)

# An endpoint: each api_* function of serve_api.c has its line in tippe_serve_routes, and
# each line names one of them.
api = read("src/serve/serve_api.c")
functions = set(re.findall(r"^static (?:void|int) (api_[a-z_]+)\(", api, re.M))
routes = re.search(r"tippe_serve_routes\[\] = \{(.*?)\n\};", api, re.S)
routed = set(re.findall(r'\{"/api/[a-z_]+", \d, (?:\d|SERVE_LANE_[A-Z]+), '
                        r'((?:tippe_serve_)?api_[a-z_]+)(?:, \d)?\}', routes.group(1))) \
    if routes else set()
# an endpoint of its own file (serve_gcode.c's tippe_serve_api_gcode) is defined there
for fn in sorted(f for f in routed if f.startswith("tippe_serve_")):
    checks += 1
    serve_dir = os.path.join(src_root, "src", "serve")
    if not any(re.search(r"^void %s\(" % fn, read(os.path.join("src", "serve", f)), re.M)
               for f in os.listdir(serve_dir) if f.endswith(".c")):
        fail("endpoints: %s is routed but defined in no file of src/serve/" % fn)
    routed.discard(fn)
checks += 1
if not functions or not routed:
    fail("endpoints: src/serve/serve_api.c: no endpoint functions or no tippe_serve_routes")
for fn in sorted(functions ^ routed):
    checks += 1
    fail("endpoints: %s is %s" % (fn, "not in tippe_serve_routes" if fn in functions
                                     else "routed but not a function of serve_api.c"))

# An export format: each format header export.c includes is a file export.c calls.
for inc in re.findall(r'#include "export/([a-z_]+)\.h"', read("src/export/export.c")):
    checks += 1
    if not calls("src/export/export.c", "src/export/%s.c" % inc):
        fail("export formats: src/export/export.c includes export/%s.h but calls nothing "
             "of src/export/%s.c" % (inc, inc))

# A print rule: the settings in print.h, the rules in print_slicer.c, read from the
# design's print block.
checks += 1
if "} tippe_print_settings;" not in read("include/tippe/print.h") or \
        "tippe_print_slice_layers" not in defined.get("src/print/print_slicer.c", set()) or \
        "tippe_print_settings" not in read("src/design/design_parts.c"):
    fail("print rules: tippe_print_settings (include/tippe/print.h), the layers of "
         "src/print/print_slicer.c and the print block's reader (src/design/design_parts.c) "
         "are not where docs/architecture.md puts them")

# A friction law: its table and the table's questions are src/physics/friction_laws.c's,
# and the option rules (src/launch/friction_options.c), the scenario reader and the
# command's --friction help ask it (the dynamics' force is checked against the table by
# tests/test_physics_friction_laws.c).
LAWS = "src/physics/friction_laws.c"
for fn in ("tippe_friction_law_at", "tippe_friction_law_type_of", "tippe_friction_law_find",
           "tippe_friction_law_help"):
    checks += 1
    if fn not in defined.get(LAWS, set()):
        fail("friction laws: %s is not defined in %s (docs/architecture.md)" % (fn, LAWS))
for asker in ("src/launch/friction_options.c", "src/scenario/scenario.c"):
    checks += 1
    if not calls(asker, LAWS):
        fail("friction laws: %s does not ask the laws' table (%s)" % (asker, LAWS))
checks += 1
if not any(calls(k, LAWS) for k in defined if k.startswith("src/cli/")):
    fail("friction laws: no file of src/cli/ asks the laws' table (--friction's help)")

# An endpoint reads its request with serve_request.c's strict readers.
checks += 1
if not calls("src/serve/serve_api.c", "src/serve/serve_request.c"):
    fail("endpoints: src/serve/serve_api.c does not read requests with serve_request.c")

# An export format: each internal header of export/ is the header of a file of its name,
# and export.h's tippe_export_request asks for the formats.
for h in sorted(os.listdir(os.path.join(src_root, "src", "export"))):
    if h.endswith(".h"):
        checks += 1
        if not os.path.exists(os.path.join(src_root, "src", "export", h[:-2] + ".c")):
            fail("export formats: src/export/%s has no src/export/%s.c" % (h, h[:-2]))
checks += 1
if "tippe_export_request" not in read("include/tippe/export.h"):
    fail("export formats: include/tippe/export.h has no tippe_export_request")

# A design field: every key the reader of src/design/design_parts.c accepts is documented
# in docs/design-format.md.
parts_c, fmt_md = read("src/design/design_parts.c"), read("docs/design-format.md")
keys = set()
for m in re.finditer(r"const char \*const [a-z_]+keys\[\] = \{(.*?)\};", parts_c, re.S):
    keys |= set(re.findall(r'"([a-z_0-9]+)"', m.group(1)))
checks += 1
if len(keys) < 20:
    fail("design fields: src/design/design_parts.c: found only %d keys (its lists changed "
         "shape?)" % len(keys))
for k in sorted(keys):
    checks += 1
    if "`%s`" % k not in fmt_md and '"%s"' % k not in fmt_md:
        fail("design fields: '%s' (src/design/design_parts.c) is not in docs/design-format.md" % k)

# 5. names and sizes: a file named like a public header lives in that module's folder; a
# public header stays readable (physics.h, 1257 lines, became theory.h, physics.h and
# launch.h with top.h: issue 34.4).
LONG_HEADERS_PENDING = set()
headers = sorted(f for f in os.listdir(os.path.join(src_root, "include", "tippe"))
                 if f.endswith(".h"))
for folder in sorted(os.listdir(os.path.join(src_root, "src"))):
    fdir = os.path.join(src_root, "src", folder)
    if not os.path.isdir(fdir):
        continue
    for f in sorted(os.listdir(fdir)):
        checks += 1
        stem = os.path.splitext(f)[0]
        if f.endswith((".c", ".h")) and stem + ".h" in headers and stem != folder:
            fail("file names: src/%s/%s shares the name of include/tippe/%s.h" %
                 (folder, f, stem))
for h in headers:
    checks += 1
    n = read(os.path.join("include", "tippe", h)).count("\n")
    if n > 700 and h not in LONG_HEADERS_PENDING:
        fail("sizes: include/tippe/%s has %d lines (at most 700)" % (h, n))

# 6. a friction law is one table entry (src/physics/friction_laws.c): no source
#    outside physics/ names a law by its enum (issue 34.1); the verbs, the server and
#    the readers ask the table what a law takes, says and needs.
LAW = re.compile(r"TIPPE_FRICTION_[A-Z]")
for d, _, files in os.walk(os.path.join(src_root, "src")):
    rel = os.path.relpath(d, os.path.join(src_root, "src"))
    if rel == "physics" or rel.startswith("physics" + os.sep):
        continue
    for f in sorted(files):
        if f.endswith(".c"):
            checks += 1
            with open(os.path.join(d, f), encoding="utf-8") as fh:
                n = len(LAW.findall(fh.read()))
            if n:
                fail("friction law named outside physics/: src/%s/%s names TIPPE_FRICTION_* %d "
                     "times (ask the law's table entry, tippe_friction_law_type_of)" %
                     (rel, f, n))

# 7. a path relative to the file that names it is one rule (src/base/path.c,
#    tippe_path_*; issue 34.3): no other source splits a path at its last '/' by hand.
SPLIT = re.compile(r"strrchr\([^;]*'/'\)")
for d, _, files in os.walk(os.path.join(src_root, "src")):
    rel = os.path.relpath(d, os.path.join(src_root, "src"))
    for f in sorted(files):
        if f.endswith(".c") and not (rel == "base" and f == "path.c"):
            checks += 1
            with open(os.path.join(d, f), encoding="utf-8") as fh:
                n = len(SPLIT.findall(fh.read()))
            if n:
                fail("paths: src/%s/%s splits a path at '/' by hand %d times (tippe_path_dir, "
                     "_base, _beside, _stem or _ext of src/base/path.c)" % (rel, f, n))

print("check_house: %d objects, %d file-to-file calls, %d includes and symbols checked" %
      (len(defined), sum(len(b) for b in edges.values()), checks))
print("%d passed, %d failed" % (checks - len(failures), len(failures)))
sys.exit(1 if failures else 0)
