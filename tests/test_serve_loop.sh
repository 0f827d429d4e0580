#!/usr/bin/env bash
# The maker's loop on tippe serve's page (issue 37, tests/serve_loop.py): a shipped design,
# edited, made printed, its G-code uploaded, its mass weighed; at each step the page's
# verdict is tippe build's on the same design written to a file. Needs Debian's chromium,
# chromium-driver and python3-selenium; the G-code steps need prusa-slicer (skipped, saying
# so, without it).
# Usage: test_serve_loop.sh TIPPE
set -euo pipefail
tippe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
for tool in /usr/bin/chromium /usr/bin/chromedriver; do
    [ -x "$tool" ] || { echo "SKIPPED: $tool is not installed (apt-get install chromium chromium-driver)"; exit 0; }
done
py=/usr/bin/python3
[ -x "$py" ] || py=python3
"$py" -c "import selenium" 2>/dev/null || { echo "SKIPPED: python3-selenium is not installed"; exit 0; }
exec "$py" "$(dirname "$0")/serve_loop.py" "$tippe" "$(dirname "$tippe")/serve-artefacts"
