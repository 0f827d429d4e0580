#!/usr/bin/env bash
# docs/python.md's example, the text itself, run with Debian's python3 over the
# build's libtippe: it writes its figure (the zone bar and theta(t)), a PNG
# of the size it asks for. Skipped, saying which package, without Matplotlib.
# Usage: test_python_example.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
build=$(cd "$(dirname "$tippe")" && pwd)
py=/usr/bin/python3
for m in numpy:python3-numpy matplotlib:python3-matplotlib; do
    if ! $py -c "import ${m%%:*}" 2>/dev/null; then
        echo "SKIPPED: docs/python.md's example needs ${m#*:} (apt-get install ${m#*:})"
        exit 0
    fi
done
sed -n '/^```python$/,/^```$/p' docs/python.md | sed '1d;$d' >"$tmp/example.py"
check "docs/python.md holds the example" grep -q "d.check(15)" "$tmp/example.py"
(cd "$tmp" && TIPPE_LIBRARY=$build/libtippe.so.0 PYTHONPATH=$OLDPWD/python $py example.py) 2>"$tmp/err"
check "the example runs" test $? -eq 0 || cat "$tmp/err"
# 8 x 5 inches at 100 dpi
check "it draws an 800 x 500 PNG" $py -c 'import struct,sys; b=open(sys.argv[1],"rb").read(24); assert b[:8]==b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", b[16:24])==(800, 500)' "$tmp/zones-and-theta.png"
# TIPPE_KEEP_PNG=FILE keeps the figure (docs/img/python-zones-theta.png is made so)
[ -n "${TIPPE_KEEP_PNG:-}" ] && cp "$tmp/zones-and-theta.png" "$TIPPE_KEEP_PNG"
finish
