#!/usr/bin/env bash
# tippe serve's page in a real headless Chromium (tests/serve_browser.py): edit a
# design until its 3-in-1 verdict changes and see tippe sweep's numbers, check a
# launch, download the build zip, no console errors. Screenshots of each step are
# kept in the build folder's serve-artefacts/. Needs Debian's chromium,
# chromium-driver and python3-selenium (tools/deps.sh installs them in CI).
# Usage: test_serve_browser.sh TIPPE
set -euo pipefail
source "$(dirname "$0")/lib.sh"
run_in_chromium serve_browser.py "$1"
