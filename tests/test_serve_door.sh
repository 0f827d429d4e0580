#!/usr/bin/env bash
# tippe serve's door (tests/serve_door.py): log lines, UTF-8 answers, \u0000,
# numbers beyond a double, chunked bodies at the cap, Host headers, slow connections.
# Usage: test_serve_door.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
exec python3 "$(dirname "$0")/serve_door.py" "$tippe"
