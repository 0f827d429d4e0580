# Shared helpers of the shell tests (tests/test_*.sh), sourced, never run:
#   source "$(dirname "$0")/lib.sh"
#   setup "$@"     # $tippe, $tmp, the counters
#   check "what" COMMAND...
#   finish         # last line: prints the summary, its status is the test's
# Not a test itself: its name stays out of the test_*.sh glob in tests/CMakeLists.txt.
set -u

# setup TIPPE: the test's name (from the script's), $tippe (the command under
# test, given by ctest), counters, and a private scratch directory $tmp removed
# on exit however the test ends.
setup() {
    test_name=$(basename "$0" .sh)
    tippe=${1:?usage: bash tests/$test_name.sh /path/to/tippe (from the repository root)}
    passed=0
    failed=0
    tmp=$(mktemp -d "${TMPDIR:-/tmp}/tippe-$test_name-XXXXXX") || exit 1
    trap 'rm -rf "$tmp"' EXIT
    exec 3>&1 # the test's own stdout, for FAIL lines even inside redirected checks
}

ok() { passed=$((passed + 1)); }
bad() { # bad MESSAGE: a failed check, said on the test's stdout (ctest keeps it in the log)
    failed=$((failed + 1))
    echo "FAIL: $*" >&3
}

# check DESCRIPTION COMMAND...: passes when COMMAND succeeds. Its status is the
# check's, so that a test can skip what depends on it (check ... || continue).
check() {
    local what=$1
    shift
    if "$@"; then
        ok
        return 0
    fi
    bad "$what"
    return 1
}

# exits STATUS ARGS...: tippe ARGS exits with STATUS (output discarded).
exits() {
    local want=$1
    shift
    "$tippe" "$@" >/dev/null 2>&1
    [ $? -eq "$want" ]
}

# expect_fail NAME STATUS PATTERN... -- ARGS...: tippe ARGS must exit with STATUS,
# print every PATTERN (fixed strings) on stderr and nothing on stdout. One check.
expect_fail() {
    local name=$1 want=$2
    shift 2
    local pats=()
    while [ "$1" != "--" ]; do
        pats+=("$1")
        shift
    done
    shift
    "$tippe" "$@" >"$tmp/out" 2>"$tmp/err"
    local st=$?
    if [ "$st" -ne "$want" ]; then
        bad "$name: exit $st, want $want; stderr: $(cat "$tmp/err")"
        return
    fi
    local p
    for p in "${pats[@]}"; do
        if ! grep -qF -- "$p" "$tmp/err"; then
            bad "$name: stderr lacks '$p': $(cat "$tmp/err")"
            return
        fi
    done
    if [ -s "$tmp/out" ]; then
        bad "$name: printed on stdout although it failed"
        return
    fi
    ok
}

# json_edit IN OUT PYTHON: writes OUT, the JSON file IN after the python
# statements PYTHON have changed its contents, the dict d.
json_edit() {
    python3 - "$1" "$2" "$3" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(d, open(sys.argv[2], "w"), indent=1)
EOF
}

# json_ok FILE EXPRESSION: the python EXPRESSION on the file's JSON, o, is true.
json_ok() {
    python3 -c "import json,math,sys; o=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$1" 2>/dev/null
}

# skip REASON: the test cannot run here; says why, reports nothing checked, exits 0.
skip() {
    echo "$test_name: SKIPPED: $*"
    finish
    exit 0
}

# finish: the summary line "test_x: N passed, M failed"; succeeds when none failed.
finish() {
    echo "$test_name: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

# run_in_chromium SCRIPT.py TIPPE: the page tests' launcher (test_serve_browser.sh,
# test_serve_page.sh, test_serve_loop.sh). Skips, naming what is missing, without
# Debian's chromium, chromium-driver or python3-selenium; else runs tests/SCRIPT.py with
# the absolute tippe and the build folder's serve-artefacts/ for its screenshots.
run_in_chromium() {
    local script=$1 tippe_abs
    tippe_abs=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
    for tool in /usr/bin/chromium /usr/bin/chromedriver; do
        [ -x "$tool" ] || { echo "SKIPPED: $tool is not installed (apt-get install chromium chromium-driver)"; exit 0; }
    done
    # Debian's python3-selenium is for Debian's python3 (not another one first on PATH)
    local py=/usr/bin/python3
    [ -x "$py" ] || py=python3
    "$py" -c "import selenium" 2>/dev/null || { echo "SKIPPED: python3-selenium is not installed"; exit 0; }
    exec "$py" "$(dirname "$0")/$script" "$tippe_abs" "$(dirname "$tippe_abs")/serve-artefacts"
}
