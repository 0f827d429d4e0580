#!/usr/bin/env bash
# tippe serve's lanes' budgets (tests/serve_budget.py): the advice and the exclusive lane
# have their own, --slow-budget (4 x --budget), still a limit on each request.
# Usage: test_serve_budget.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
exec python3 "$(dirname "$0")/serve_budget.py" "$tippe"
