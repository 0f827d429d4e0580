#!/usr/bin/env bash
# What tippe serve's requests cost (tests/serve_cost.py): the verdict within twice a
# sweep's CPU, the advice kept per design, long jobs not holding the sweep's workers.
# Usage: test_serve_cost.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
exec python3 "$(dirname "$0")/serve_cost.py" "$tippe"
