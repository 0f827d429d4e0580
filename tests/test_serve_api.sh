#!/usr/bin/env bash
# tippe serve's API (tests/serve_api.py): every endpoint against the command's --json
# on every shipped design, bad input, the doors (Host, Origin, token, '..'), a full
# queue, the budget, and SIGTERM leaving no temporary.
# Usage: test_serve_api.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
exec python3 "$(dirname "$0")/serve_api.py" "$tippe"
