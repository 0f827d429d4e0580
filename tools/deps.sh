#!/usr/bin/env bash
# Installs the Debian 12 packages tippe needs, only those that are missing.
# Sourced by tools/quickstart.sh and .ci/run; safe to run twice.
set -euo pipefail
TIPPE_DEBS=(build-essential cmake pkg-config libgsl-dev libcjson-dev libplplot-dev
            plplot-driver-cairo libopenmpi-dev openmpi-bin python3 python3-numpy python3-scipy
            libnlopt-dev lib3mf-dev libgeos-dev admesh python3-stl libcairo2-dev
            libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libavfilter-dev ffmpeg
            libmicrohttpd-dev libzip-dev)
# CI also renders the OpenSCAD export (tests/test_export_cli.sh): measured on this
# machine, installing openscad adds 13 packages (24 MiB) beyond the list above and
# took 26 s; the render check takes ~15 s. Users get it only if they ask.
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_OPENSCAD:-}" = "1" ]; then
  TIPPE_DEBS+=(openscad)
fi
# CI also slices with PrusaSlicer 2.5 (tests/test_slicer.sh, tools/slice.sh; headless, no
# display): measured on this machine, installing prusa-slicer adds 29 packages (84 MB to
# download, 375 MB installed) beyond the list above and took 11 s; the test takes ~10 s.
# Users get it only if they ask (TIPPE_WITH_SLICER=1).
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_SLICER:-}" = "1" ]; then
  TIPPE_DEBS+=(prusa-slicer)
fi
# CI also drives tippe serve's page in a real headless Chromium (tests/test_serve_browser.sh,
# selenium with Debian's chromedriver: no browser download, no npm). Measured on this
# machine: 21 packages beyond the list above, 125 MB to fetch, 399 MB on disk, 31 s to
# install; the browser test takes ~10 s. Users get them only if they ask.
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_BROWSER:-}" = "1" ]; then
  TIPPE_DEBS+=(chromium chromium-driver python3-selenium)
fi
# CI also runs the fuzz targets (tests/test_fuzz.sh, docs/fuzzing.md): clang and its
# libFuzzer runtime. Measured on Debian 12 with the list above installed: 12 packages,
# 45 MB to fetch (3.9 s here), 259 MiB unpacked (6.1 s); building the targets then takes
# a few minutes on one core, once per build directory. Without clang the test skips.
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_FUZZ:-}" = "1" ]; then
  TIPPE_DEBS+=(clang libclang-rt-dev)
fi
# CI also builds, lints and installs the .deb and draws docs/python.md's figure
# (tests/test_deb.sh, tests/test_python_example.sh): lintian and Matplotlib; man-db
# (man -w) and dpkg-dev (dpkg-shlibdeps) come with build-essential. Measured on this
# machine with the list above installed: 150 packages (lintian's Perl, Matplotlib's
# fonts and SymPy); test_deb takes ~35 s (apt install and remove included), the
# example ~5 s. Users get them only if they ask (TIPPE_WITH_PACKAGING=1).
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_PACKAGING:-}" = "1" ]; then
  TIPPE_DEBS+=(lintian python3-matplotlib man-db)
fi
# CI also counts the files each command opens (tests/test_read_once.sh: each input read
# once) with strace. Measured on Debian 12: 1 package (and libunwind8, 51 kB, where it is
# missing), 1.3 MB to fetch, 2.8 MiB installed; the test takes ~4 s. Without it the test
# skips.
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_STRACE:-}" = "1" ]; then
  TIPPE_DEBS+=(strace)
fi
# CI also slices with CuraEngine 4.13 (tests/test_cura.sh): Debian's cura-engine, whose printer
# definitions (fdmprinter.def.json, fdmextruder.def.json) ship only in the Qt front end's package
# cura (25 MB .deb, ~88 MB installed with its Qt dependencies). So only the engine is installed
# and the definitions are taken out of cura's .deb (apt-get download, dpkg-deb -x: no Qt, no
# install) into $TIPPE_CURA_RESOURCES. Measured on this machine: cura-engine 3 packages, 1.7 MB
# to fetch, 4.9 MB installed, 12.7 s; the .deb's download 3.6 s, the definitions and extruders
# taken out in 2.2 s (4.3 MB). The test takes ~10 s. Users get it only if they ask.
TIPPE_CURA_RESOURCES="${TIPPE_CURA_RESOURCES:-/usr/local/share/tippe/cura-resources}"
with_cura=0
if [ "${CI:-}" = "true" ] || [ "${TIPPE_WITH_CURA:-}" = "1" ]; then
  TIPPE_DEBS+=(cura-engine)
  with_cura=1
fi
missing=()
for p in "${TIPPE_DEBS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "tippe: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
# Cura's printer definitions without its front end (see above): taken once
if [ "$with_cura" = 1 ] && [ ! -f "$TIPPE_CURA_RESOURCES/definitions/fdmprinter.def.json" ] &&
   [ ! -f /usr/share/cura/resources/definitions/fdmprinter.def.json ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  cura_tmp=$(mktemp -d) && chmod 755 "$cura_tmp" # apt-get download runs as _apt
  ( cd "$cura_tmp" && apt-get download cura >/dev/null &&
    dpkg-deb --fsys-tarfile cura_*.deb |
      tar -x --wildcards './usr/share/cura/resources/definitions/*' \
                        './usr/share/cura/resources/extruders/*' ) &&
    $SUDO mkdir -p "$TIPPE_CURA_RESOURCES" &&
    $SUDO cp -r "$cura_tmp/usr/share/cura/resources/definitions" \
                "$cura_tmp/usr/share/cura/resources/extruders" "$TIPPE_CURA_RESOURCES/" ||
    echo "tippe: could not take Cura's definitions out of the cura package" >&2
  rm -rf "$cura_tmp"
fi
