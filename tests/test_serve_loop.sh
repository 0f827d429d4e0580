#!/usr/bin/env bash
# The maker's loop on tippe serve's page (issue 37, tests/serve_loop.py): a shipped design,
# edited, made printed, its G-code uploaded, its mass weighed; at each step the page's
# verdict is tippe build's on the same design written to a file. Needs Debian's chromium,
# chromium-driver and python3-selenium; the G-code steps need prusa-slicer (skipped, saying
# so, without it).
# Usage: test_serve_loop.sh TIPPE
set -euo pipefail
source "$(dirname "$0")/lib.sh"
run_in_chromium serve_loop.py "$1"
