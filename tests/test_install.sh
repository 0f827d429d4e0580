#!/usr/bin/env bash
# cmake --install into a temporary prefix, then the installed command run as a
# user would, from an empty folder outside the checkout: it finds its modules in
# PREFIX/lib/tippe, its designs and tables in PREFIX/share/tippe/designs, and a
# design with no table beside it reads the installed one (docs/install.md). The
# man pages and the bash completion installed beside it are those of every verb.
# Usage: test_install.sh TIPPE (the build's tippe; its folder is the build tree)
source "$(dirname "$0")/lib.sh"
setup "$@"
build=$(cd "$(dirname "$tippe")" && pwd)
tippe=$build/$(basename "$tippe")
src=$PWD
P=$tmp/prefix
cmake --install "$build" --prefix "$P" >"$tmp/install.log" 2>&1
check "cmake --install exits 0" test $? -eq 0 || { cat "$tmp/install.log"; finish; exit; }
check "the command is in PREFIX/bin" test -x "$P/bin/tippe"
check "its modules are in PREFIX/lib/tippe" test -f "$P/lib/tippe/tippe-plot.so"
check "no module beside the installed command" bash -c '! ls "$1"/bin/*.so 2>/dev/null | grep -q .' _ "$P"
check "the shipped designs are in PREFIX/share/tippe/designs" test -f "$P/share/tippe/designs/m12-setscrew.json"
for f in materials.json catalogue.json scenarios/fig12-tip.json slicer/prusa-pla-0.4mm.ini; do
    check "$f is installed" cmp -s "designs/$f" "$P/share/tippe/designs/$f"
done

empty=$tmp/empty
mkdir -p "$empty"
cd "$empty"
# the installed command must not lean on the checkout: no designs/ here
"$P/bin/tippe" sweep "$P/share/tippe/designs/m12-setscrew.json" --json --plot zones.png >sweep.json 2>err
check "installed sweep exits 0 from an empty folder" test $? -eq 0
check "... and draws its plot (tippe-plot.so from PREFIX/lib/tippe)" test -s zones.png
"$tippe" sweep "$src/designs/m12-setscrew.json" --json >build.json
check "... with the numbers of the build tree's command" python3 - sweep.json build.json <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
assert a["zones"] == b["zones"], "zones differ"
PY
"$P/bin/tippe" materials --json >m.json 2>err
check "installed materials lists the installed table" python3 -c 'import json,sys; assert json.load(open("m.json"))["file"] == sys.argv[1] + "/share/tippe/designs/materials.json"' "$(cd "$P" && pwd -P)"
mkdir lonely
cp "$P/share/tippe/designs/shell-rod-nylon.json" lonely/
"$P/bin/tippe" eval lonely/shell-rod-nylon.json --z2 5 >/dev/null 2>err
check "a design without a table beside it reads the installed one, with a note" \
    grep -q "note: lonely/shell-rod-nylon.json: materials: no materials.json beside the design: its materials are those of the shipped table $(cd "$P" && pwd -P)/share/tippe/designs/materials.json" err
# nothing at all: the error names the field that needs a table
mv "$P/share/tippe/designs/materials.json" "$tmp/away.json"
"$P/bin/tippe" eval lonely/shell-rod-nylon.json --z2 5 >out 2>err
check "no table anywhere: exit 2" test $? -eq 2
check "... naming the field that needs one" grep -q "lonely/shell-rod-nylon.json: parts\[[0-9]\].material: '.*' needs a materials table: there is no lonely/materials.json beside the design and no installed one" err
mv "$tmp/away.json" "$P/share/tippe/designs/materials.json"

# tippe serve without --designs lists the installed designs (a port of its own; stopped by timeout)
timeout 8 "$P/bin/tippe" serve --listen 127.0.0.1:0 >serve.out 2>&1 &
serve_pid=$!
for _ in 1 2 3 4 5 6 7 8 9 10; do grep -q "http://" serve.out && break; sleep 0.3; done
url=$(grep -o "http://[^ ]*" serve.out | head -1)
check "installed serve lists the installed designs" python3 -c 'import json, sys, urllib.request
d = json.load(urllib.request.urlopen(sys.argv[1] + "api/designs", timeout=5))
assert "m12-setscrew" in [x["name"] for x in d["designs"]], d' "$url"
kill "$serve_pid" 2>/dev/null
wait "$serve_pid" 2>/dev/null

# man pages: tippe(1) and one per verb, each naming its options as --help does
verbs=$("$tippe" --help | awk '/^verbs:/{v=1;next} v&&/^  [a-z]/{print $1} /^$/&&v&&n++{v=0}')
check "tippe.1 is installed" test -f "$P/share/man/man1/tippe.1.gz"
check "tippe-mpi.1 is installed" test -f "$P/share/man/man1/tippe-mpi.1.gz"
for v in $verbs; do
    page=$P/share/man/man1/tippe-$v.1.gz
    check "tippe-$v.1 is installed" test -f "$page" || continue
    MANWIDTH=200 man -l "$page" 2>/dev/null >man.txt
    for o in $("$tippe" "$v" --help | grep -oE '^  --[a-z0-9-]+' | tr -d ' '); do
        grep -q -- "$o" man.txt || { bad "tippe-$v(1) lacks $o"; continue; }
        ok
    done
done
# completion: verbs, a verb's options, design files
comp=$P/share/bash-completion/completions/tippe
check "the completion is installed" test -f "$comp"
complete_line() { # complete_line WORDS...: what TAB offers for the last word
    bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _tippe; printf "%s\n" "${COMPREPLY[@]}"' _ "$comp" "$@"
}
check "TAB after tippe sw offers sweep" test "$(complete_line tippe sw)" = sweep
check "TAB after tippe sweep --ph offers --phase-plot" test "$(complete_line tippe sweep --ph)" = --phase-plot
check "TAB after tippe eval lonely/ offers the design" test "$(complete_line tippe eval lonely/)" = lonely/shell-rod-nylon.json

# libtippe.so: SONAME, only tippe_ symbols exported, and docs/library.md's example
# compiled against the installed headers and library (pkg-config) and run
lib=$(ls "$P"/lib*/libtippe.so.0 "$P"/lib/*/libtippe.so.0 2>/dev/null | head -1)
check "libtippe.so.0 is installed" test -n "$lib" || { finish; exit; }
check "its SONAME is libtippe.so.0" bash -c 'objdump -p "$1" | grep -q "SONAME *libtippe.so.0$"' _ "$lib"
nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBR]$/ {print $3}' | grep -v '^tippe_' | grep -vE '^(_init|_fini|_edata|_end|__bss_start)$' >"$tmp/foreign" || true
check "libtippe.so exports only tippe_ names" test ! -s "$tmp/foreign" || head "$tmp/foreign"
libdir=$(dirname "$lib")
sed -n '/^```c$/,/^```$/p' "$src/docs/library.md" | sed '1d;$d' >zones.c
check "docs/library.md holds the example" grep -q tippe_sweep_design zones.c
PKG_CONFIG_PATH=$libdir/pkgconfig cc -Wall -Werror -o zones zones.c \
    $(PKG_CONFIG_PATH=$libdir/pkgconfig pkg-config --cflags --libs tippe) 2>cc.err
check "the example compiles against the installed library" test $? -eq 0 || cat cc.err
LD_LIBRARY_PATH=$libdir ./zones "$P/share/tippe/designs/m12-setscrew.json" >zones.txt 2>err
check "the example runs" test $? -eq 0
check "it uses the installed library" bash -c 'LD_LIBRARY_PATH="$1" ldd ./zones | grep -q "libtippe.so.0 => $1/libtippe.so.0"' _ "$libdir"
"$tippe" sweep "$src/designs/m12-setscrew.json" --csv csv.csv >/dev/null
# the same zones as tippe sweep --csv, to the 3 decimals it prints
check "its zone table is tippe sweep's" python3 - zones.txt csv.csv <<'PY'
import csv, sys
rows = open(sys.argv[1]).read().split("\n")[1:]
rows = [r.split() for r in rows if r.strip()]
ref = list(csv.DictReader(open(sys.argv[2])))
assert len(rows) == len(ref) and rows, (rows, ref)
for r, c in zip(rows, ref):
    want = [c["group"]] + ["%.3f" % float(c[k]) for k in
                           ("z2_from_mm", "z2_to_mm", "width_mm", "robust_width_mm")]
    assert r == want, (r, want)
PY

# the Python module installed beside the library finds it (docs/python.md)
if /usr/bin/python3 -c 'import numpy' 2>/dev/null; then
    env -u TIPPE_LIBRARY PYTHONPATH="$P/lib/python3/dist-packages" /usr/bin/python3 -c \
        'import sys, tippe; print(tippe.library_path()); print(tippe.sweep(sys.argv[1]))' \
        "$P/share/tippe/designs/m12-setscrew.json" >py.txt 2>err
    check "the installed Python module runs from an empty folder" test $? -eq 0 || cat err
    check "... over the installed libtippe" grep -qx "$P/lib/libtippe.so.0" py.txt
    check "... and prints the zone table" grep -Eq "^IIb +8\.689 +16\.360" py.txt
else
    echo "SKIPPED: the Python module's check (python3-numpy is not installed)"
fi
cd "$src"
finish
