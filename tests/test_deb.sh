#!/usr/bin/env bash
# The .deb as a user meets it (docs/install.md): tools/deb.sh packs the tested
# build, apt installs it with what it depends on, and from an empty folder outside
# the checkout: tippe sweep of an installed design, man -w tippe-sweep, the bash
# completion, docs/library.md's C example against the installed library and the
# Python one-liner; apt remove then leaves none of its files behind. The packages
# apt pulled in are removed again, so the machine is as it was. Needs root and apt;
# skipped (saying why) without them or when a tippe package is already installed.
# Usage: test_deb.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
build=$(cd "$(dirname "$tippe")" && pwd)
src=$PWD
if [ "$(id -u)" -ne 0 ]; then echo "SKIPPED: test_deb needs root (apt install)"; exit 0; fi
if ! command -v apt-get >/dev/null || ! command -v dpkg-deb >/dev/null; then
    echo "SKIPPED: test_deb needs apt and dpkg"; exit 0
fi
if dpkg-query -W -f='${Status}' tippe 2>/dev/null | grep -q installed; then
    echo "SKIPPED: a tippe package is already installed; test_deb would replace it"; exit 0
fi
deb=$(tools/deb.sh "$build" 2>"$tmp/deb.log" | tail -1)
check "tools/deb.sh builds the .deb" test -f "$deb" || { tail -20 "$tmp/deb.log"; finish; exit; }
check "its name is tippe_VERSION_ARCH.deb" bash -c '[[ $(basename "$1") =~ ^tippe_[0-9.]+_[a-z0-9]+\.deb$ ]]' _ "$deb"
check "Depends lists what the command opens itself (NLopt, FFmpeg, PLplot's cairo driver)" \
    bash -c 'dpkg-deb -f "$1" Depends | grep -q "libnlopt0.*libavcodec.*plplot-driver-cairo\|plplot-driver-cairo.*libnlopt0.*libavcodec"' _ "$deb"
check "Suggests prusa-slicer and openscad" bash -c 'dpkg-deb -f "$1" Suggests | grep -q "prusa-slicer, openscad"' _ "$deb"
# lintian: no error, and only the warnings docs/install.md explains
if command -v lintian >/dev/null; then
    lintian "$deb" 2>/dev/null | grep -E '^[EW]:' | sed -E 's/^([EW]): tippe: ([a-z0-9-]+).*/\1 \2/' | sort -u >"$tmp/lintian"
    printf '%s\n' "W link-to-shared-library-in-wrong-package" "W package-name-doesnt-match-sonames" \
        "W pkg-config-unavailable-for-cross-compilation" | sort >"$tmp/explained"
    check "lintian finds only the warnings docs/install.md explains" \
        bash -c '! comm -23 "$1" "$2" | grep .' _ "$tmp/lintian" "$tmp/explained"
    while read -r _ tag; do
        grep -q "$tag" "$src/docs/install.md" || bad "docs/install.md does not explain $tag"
    done <"$tmp/explained"
else
    echo "SKIPPED: lintian (apt-get install lintian)"
fi
dpkg-query -W -f='${Package}\n' | sort >"$tmp/before"
cp "$deb" "$tmp/"
DEBIAN_FRONTEND=noninteractive apt-get install -y "$tmp/$(basename "$deb")" >"$tmp/apt.log" 2>&1
check "apt install ./tippe_*.deb" test $? -eq 0 || tail -20 "$tmp/apt.log"
dpkg -L tippe | sort >"$tmp/files"
dpkg-query -W -f='${Package}\n' | sort >"$tmp/after"
comm -13 "$tmp/before" "$tmp/after" | grep -vx tippe >"$tmp/pulled" || true

mkdir -p "$tmp/empty" && cd "$tmp/empty"
check "tippe is on the PATH" test "$(command -v tippe)" = /usr/bin/tippe
tippe sweep /usr/share/tippe/designs/m12-setscrew.json >sweep.txt 2>err
check "tippe sweep /usr/share/tippe/designs/m12-setscrew.json" test $? -eq 0 || cat err
check "... prints its zone table" grep -q "3-in-1" sweep.txt
tippe sweep /usr/share/tippe/designs/m12-setscrew.json --plot z.png >/dev/null 2>err
check "... and draws (a module from /usr/lib/tippe)" test -s z.png || cat err
check "man -w tippe-sweep" test "$(man -w tippe-sweep 2>/dev/null)" = /usr/share/man/man1/tippe-sweep.1.gz
check "the completion offers sweep" bash -c 'source /usr/share/bash-completion/completions/tippe; COMP_WORDS=(tippe swe); COMP_CWORD=1; _tippe; [ "${COMPREPLY[*]}" = sweep ]'
sed -n '/^```c$/,/^```$/p' "$src/docs/library.md" | sed '1d;$d' >zones.c
cc -Wall -Werror -o zones zones.c $(pkg-config --cflags --libs tippe) 2>cc.err
check "docs/library.md's example compiles against the installed libtippe" test $? -eq 0 || cat cc.err
./zones /usr/share/tippe/designs/m12-setscrew.json >zones.txt 2>err
check "... and prints the zone table" grep -Eq "^IIb +8\.689 +16\.360" zones.txt || cat err zones.txt
if /usr/bin/python3 -c 'import numpy' 2>/dev/null; then
    env -u PYTHONPATH -u TIPPE_LIBRARY /usr/bin/python3 -c 'import tippe; print(tippe.sweep("/usr/share/tippe/designs/m12-setscrew.json"))' >py.txt 2>err
    check "the Python one-liner" grep -Eq "^IIb +8\.689 +16\.360" py.txt || cat err
fi
cd "$src"

DEBIAN_FRONTEND=noninteractive apt-get remove -y tippe >"$tmp/rm.log" 2>&1
check "apt remove tippe" test $? -eq 0
check "dpkg no longer knows the package (not even as removed, rc)" bash -c '! dpkg-query -W tippe >/dev/null 2>&1'
left=0
while read -r f; do
    [ -e "$f" ] && [ ! -d "$f" ] && { echo "left behind: $f"; left=1; }
done <"$tmp/files"
for d in /usr/share/tippe /usr/lib/tippe /usr/include/tippe /usr/share/doc/tippe; do
    [ -e "$d" ] && { echo "left behind: $d"; left=1; }
done
check "nothing of it is left" test $left -eq 0
# what apt pulled in for it goes again: the machine is as it was
if [ -s "$tmp/pulled" ]; then
    DEBIAN_FRONTEND=noninteractive apt-get purge -y $(cat "$tmp/pulled") >>"$tmp/rm.log" 2>&1
fi
dpkg-query -W -f='${Package}\n' | sort >"$tmp/end"
check "the packages are those before the test" cmp -s "$tmp/before" "$tmp/end"
finish
