#!/usr/bin/env bash
# Every command shown in README.md and docs/*.md runs as written: each command
# block (an indented or fenced code block whose first line is a command:
# build/..., tools/..., mpirun, mkdir, for, time, export, cmake, a=...) is run
# in a scratch directory where `build` is the tested tippe's directory,
# `designs` and `tools` are the repository's, and `docs/`, `out/` are empty
# scratch folders, so that every output lands in scratch; an output anywhere but
# under out/ or docs/img/ is a failure (examples must not litter the
# repository). A failure names the file, the line and the command, with the end
# of its stderr.
#
# Not run (said in the log): commands that build the project, run this suite
# or the benchmarks (cmake, tools/quickstart.sh, tools/run-tests.sh,
# tools/bench/run.sh), any block right after the line
# <!-- docs-test: skip REASON --> in the Markdown, and a command that needs an
# optional tool which is missing here: prusa-slicer (tippe slice), openscad (not installed by default,
# tools/deps.sh), mpirun, or build/tippe-mpi (built only when Open MPI was found;
# any mpirun command needs it, since tippe hands over to it). Such a command is
# recognised wherever the tool stands as a program: first, after `time` or
# VAR=value, or after a pipe, ;, && or ||.
#
# Usage: test_docs_commands.sh TIPPE [FILE.md ...] (default: README.md docs/*.md)
source "$(dirname "$0")/lib.sh"
setup "$1"
shift
repo=$(pwd)
bindir=$(cd "$(dirname "$tippe")" && pwd)
files=("$@")
[ ${#files[@]} -gt 0 ] || files=(README.md docs/*.md)

mkdir -p "$tmp/run/docs/img" "$tmp/run/out"
ln -s "$bindir" "$tmp/run/build"
ln -s "$repo/designs" "$tmp/run/designs"
ln -s "$repo/tools" "$tmp/run/tools"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# The optional tools that are missing here, for the Markdown reader below.
missing=()
for tool in openscad mpirun prusa-slicer; do
    command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
[ -x "$bindir/tippe-mpi" ] || missing+=(tippe-mpi)
export DOCS_MISSING="${missing[*]}"

# The blocks as runnable scripts: one file per block, each command preceded by
# a marker naming its file and line (read back to say which command failed).
python3 - "$tmp/blocks" "${files[@]}" <<'EOF'
import os, re, sys
out, files = sys.argv[1], sys.argv[2:]
os.makedirs(out)
COMMAND = re.compile(r"^(build/|tools/|mpirun |mkdir |for |time |export |cmake |[a-z_]+=)")
SKIP = re.compile(r"^(cmake |tools/quickstart\.sh|tools/run-tests\.sh|tools/bench/run\.sh)")
MISSING = set(os.environ.get("DOCS_MISSING", "").split())
# a program's place: the start, after `time` or VAR=value, or after | ; & ( {
PROGRAM = r"(?:^|[|;&({]\s*)(?:(?:time|env|nice)\s+|[A-Za-z_][A-Za-z0-9_]*=\S*\s+)*"
NEEDS = {"openscad": re.compile(PROGRAM + r"openscad\b"),
         # tippe slice and tools/slice.sh run PrusaSlicer's command line
         "prusa-slicer": re.compile(r"(?:^|[\s/])(?:tippe slice\b|slice\.sh\b)|" + PROGRAM + r"prusa-slicer\b"),
         "mpirun": re.compile(PROGRAM + r"(?:mpirun|mpiexec)\b")}

def needs(cmd):
    """The optional tools cmd runs (tippe-mpi with any mpirun: tippe hands over)."""
    tools = {t for t, r in NEEDS.items() if r.search(cmd)}
    if "mpirun" in tools or re.search(r"(?:^|[\s/])build/tippe-mpi\b", cmd):
        tools.add("tippe-mpi")
    return tools

def shell_quote(text):
    return "'" + text.replace("'", "'\\''") + "'"

def blocks(path):
    """(first line number, [lines], skip reason or None) of each code block."""
    lines = open(path, encoding="utf-8").read().split("\n")
    i, skip = 0, None
    while i < len(lines):
        m = re.match(r"\s*<!--\s*docs-test:\s*skip\s*(.*?)\s*-->", lines[i])
        if m:
            skip = m.group(1) or "marked in the Markdown"
        if lines[i].startswith("```"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            yield i + 2, lines[i + 1:j], skip
            skip, i = None, j + 1
            continue
        if lines[i].startswith("    ") and (i == 0 or not lines[i - 1].strip()):
            j = i
            while j < len(lines) and (lines[j].startswith("    ") or not lines[j].strip()):
                j += 1
            body = [l[4:] for l in lines[i:j]]
            while body and not body[-1].strip():
                body.pop()
            yield i + 1, body, skip
            skip, i = None, j
            continue
        if lines[i].strip() and not m:
            skip = None
        i += 1

n = 0
for path in files:
    for first, body, skip in blocks(path):
        if not body or not COMMAND.match(body[0]):
            continue
        n += 1
        with open(os.path.join(out, "%03d.sh" % n), "w") as f:
            k = 0
            while k < len(body):
                line, cmd = first + k, body[k]
                while cmd.endswith("\\") and k + 1 < len(body):  # continuation lines
                    k += 1
                    cmd = cmd[:-1] + " " + body[k].strip()
                k += 1
                if not cmd.strip():
                    continue
                where = "%s:%d" % (path, line)
                why = skip or ("builds the project, runs the suite or the benchmarks"
                               if SKIP.match(cmd) else None)
                absent = sorted(needs(cmd) & MISSING)
                if not why and absent:
                    why = "needs %s, not installed or not built here" % " and ".join(absent)
                if why:
                    f.write("echo %s >&4\n" % shell_quote("SKIPPED %s: %s (%s)" % (where, cmd, why)))
                    continue
                f.write("echo %s >&5\n" % shell_quote("%s %s" % (where, cmd)))
                f.write(cmd + "\n")
EOF

for block in "$tmp"/blocks/*.sh; do
    [ -e "$block" ] || break
    # set -e: the block stops at its first failing command, named by the last marker
    (cd "$tmp/run" && bash -e "$block" >"$tmp/out" 2>"$tmp/err" 4>>"$tmp/skipped" 5>"$tmp/last")
    st=$?
    where=$(tail -n 1 "$tmp/last")
    if [ $st -ne 0 ]; then
        bad "${where%% *}: exit $st: ${where#* }
$(tail -n 5 "$tmp/err" | sed 's/^/    /')"
    elif [ -n "$where" ]; then # a block of skipped commands only counts for nothing
        ok
    fi
done
[ -s "$tmp/skipped" ] && sed 's/^/  /' "$tmp/skipped"
check "found command blocks to run" test "$passed" -gt 0
# Examples write under out/ (ignored by git), or regenerate docs/img/; nothing
# lands in the repository's root or elsewhere in it (issue 19.12).
stray=$(cd "$tmp/run" && { ls -A | grep -vxE 'build|designs|tools|out|docs'
    ls -A docs | grep -vx img | sed 's|^|docs/|'; })
check "the examples wrote only under out/ and docs/img/, not: $(echo $stray)" test -z "$stray"
finish
