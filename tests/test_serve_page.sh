#!/usr/bin/env bash
# The maker's loop on tippe serve's page (issue 37) in headless Chromium
# (tests/serve_page.py): where the model does not hold, the sheet's launch checks and
# pole fixes, the launch line, the zone table's notes and the page's words, each against
# what the commands print. Screenshots in the build folder's serve-artefacts/. Needs
# Debian's chromium, chromium-driver and python3-selenium (tools/deps.sh).
# Usage: test_serve_page.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
for tool in /usr/bin/chromium /usr/bin/chromedriver; do
    [ -x "$tool" ] || { echo "SKIPPED: $tool is not installed (apt-get install chromium chromium-driver)"; exit 0; }
done
# Debian's python3-selenium is for Debian's python3 (not another one first on PATH)
py=/usr/bin/python3
[ -x "$py" ] || py=python3
"$py" -c "import selenium" 2>/dev/null || { echo "SKIPPED: python3-selenium is not installed"; exit 0; }
exec "$py" "$(dirname "$0")/serve_page.py" "$tippe" "$(dirname "$tippe")/serve-artefacts"
