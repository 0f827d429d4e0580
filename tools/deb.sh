#!/usr/bin/env bash
# Builds tippe's .deb (docs/install.md): the build tree BUILD (default build/, made
# by the quick start), brought up to date, packed by CPack (cmake/install.cmake) into
# BUILD/tippe_VERSION_ARCH.deb, whose path is printed last.
# Usage: tools/deb.sh [BUILD]
set -euo pipefail
build=${1:-build}
[ -f "$build/CPackConfig.cmake" ] || {
    echo "tools/deb.sh: $build is not a configured build tree (run tools/quickstart.sh first)" >&2
    exit 2
}
cmake --build "$build" -j"$(nproc)" >&2
rm -f "$build"/tippe_*.deb
(cd "$build" && cpack -G DEB >&2)
deb=$(ls "$build"/tippe_*.deb)
# CPack's postinst and postrm only call ldconfig, which the package's trigger
# (activate-noawait ldconfig, cmake/install.cmake) does: without them, apt remove
# leaves nothing, not even dpkg's record of the package.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dpkg-deb -R "$deb" "$tmp/pkg"
rm -f "$tmp/pkg/DEBIAN/postinst" "$tmp/pkg/DEBIAN/postrm"
dpkg-deb --root-owner-group -Zxz -b "$tmp/pkg" "$deb" >&2
echo "$deb"
