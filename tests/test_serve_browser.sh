#!/usr/bin/env bash
# tippe serve's page in a real headless Chromium (tests/serve_browser.py): edit a
# design until its 3-in-1 verdict changes and see tippe sweep's numbers, check a
# launch, download the build zip, no console errors. Screenshots of each step are
# kept in the build folder's serve-artefacts/. Needs Debian's chromium,
# chromium-driver and python3-selenium (tools/deps.sh installs them in CI).
# Usage: test_serve_browser.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
for tool in /usr/bin/chromium /usr/bin/chromedriver; do
    [ -x "$tool" ] || { echo "SKIPPED: $tool is not installed (apt-get install chromium chromium-driver)"; exit 0; }
done
# Debian's python3-selenium is for Debian's python3 (not another one first on PATH)
py=/usr/bin/python3
[ -x "$py" ] || py=python3
"$py" -c "import selenium" 2>/dev/null || { echo "SKIPPED: python3-selenium is not installed"; exit 0; }
exec "$py" "$(dirname "$0")/serve_browser.py" "$tippe" "$(dirname "$tippe")/serve-artefacts"
