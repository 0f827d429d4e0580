#!/usr/bin/env bash
# Installs the Debian 12 packages tippe needs, only those that are missing.
# Sourced by tools/quickstart.sh and .ci/run; safe to run twice.
set -euo pipefail
TIPPE_DEBS=(build-essential cmake pkg-config libgsl-dev libcjson-dev libplplot-dev
            plplot-driver-cairo libopenmpi-dev openmpi-bin python3 python3-numpy python3-scipy
            libnlopt-dev lib3mf-dev admesh python3-stl libcairo2-dev
            libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libavfilter-dev ffmpeg)
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
