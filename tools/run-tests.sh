#!/usr/bin/env bash
# Builds everything with warnings as errors in build-test/ and runs every test (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Release -DTIPPE_WERROR=ON >/dev/null
cmake --build build-test -j"$(nproc)"
# Open MPI refuses to run as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir build-test --output-on-failure -j"$(nproc)" "$@"
