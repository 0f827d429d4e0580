#!/usr/bin/env bash
# The maker's loop on tippe serve's page (issue 37) in headless Chromium
# (tests/serve_page.py): where the model does not hold, the sheet's launch checks and
# pole fixes, the launch line, the zone table's notes and the page's words, each against
# what the commands print. Screenshots in the build folder's serve-artefacts/. Needs
# Debian's chromium, chromium-driver and python3-selenium (tools/deps.sh).
# Usage: test_serve_page.sh TIPPE
set -euo pipefail
source "$(dirname "$0")/lib.sh"
run_in_chromium serve_page.py "$1"
