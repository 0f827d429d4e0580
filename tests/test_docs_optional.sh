#!/usr/bin/env bash
# tests/test_docs_commands.sh on a machine without the optional tools (issue
# 19.5): OpenSCAD is installed only on request (tools/deps.sh) and tippe-mpi is
# built only when Open MPI is found, so a docs command that runs openscad,
# mpirun or build/tippe-mpi is skipped there, saying so, and the rest still
# runs; where the tools are present the same commands do run.
#
# Absent is made real, not pretended: a PATH of links to every program on
# this machine's PATH except openscad and mpirun, and a build directory with
# tippe and its modules but no tippe-mpi. Present: stand-ins for the three
# that log their arguments. Usage: test_docs_optional.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"
bindir=$(cd "$(dirname "$tippe")" && pwd)
docs_test=$(dirname "$0")/test_docs_commands.sh

# PATH without the optional tools (first of each name wins, as in a lookup)
mkdir -p "$tmp/bare"
IFS=: read -r -a path_dirs <<<"$PATH"
for dir in "${path_dirs[@]}"; do
    [ -d "$dir" ] || continue
    for prog in "$dir"/*; do
        name=${prog##*/}
        case $name in openscad | mpirun | mpiexec | orterun | prterun) continue ;; esac
        [ -x "$prog" ] && [ ! -e "$tmp/bare/$name" ] && ln -s "$prog" "$tmp/bare/$name"
    done
done
check "the bare PATH has no openscad" bash -c '! PATH=$1 command -v openscad' _ "$tmp/bare"
check "the bare PATH has no mpirun" bash -c '! PATH=$1 command -v mpirun' _ "$tmp/bare"
# a build without tippe-mpi: tippe and its modules (it finds them next to its real path)
mkdir -p "$tmp/build"
for f in "$bindir"/tippe "$bindir"/tippe-*.so; do
    ln -s "$f" "$tmp/build/${f##*/}"
done

# Markdown with each way an optional tool appears in the docs, and a plain
# command after them that must still run.
cat >"$tmp/optional.md" <<'EOF'
# optional tools

```
build/tippe export designs/m12-setscrew.json -o out --format scad
openscad -D 'show="printed"' -D fn=16 -o out/printed.stl out/m12-setscrew.scad
```

    mpirun -np 2 -x OMP_NUM_THREADS=1 build/tippe eval designs/m12-setscrew.json --z2 5
    time mpirun -np 1 build/tippe-mpi eval designs/m12-setscrew.json --z2 5 >/dev/null
    time OMP_NUM_THREADS=1 build/tippe-mpi eval designs/m12-setscrew.json --z2 5 >/dev/null

    build/tippe eval designs/m12-setscrew.json --z2 5 >out/plain.txt
EOF

# --- absent: skipped with a message naming the tool, the rest runs -------------
PATH="$tmp/bare" bash "$docs_test" "$tmp/build/tippe" "$tmp/optional.md" >"$tmp/absent.log" 2>&1
check "without openscad, mpirun, tippe-mpi: the docs test passes" test $? -eq 0 ||
    sed 's/^/    /' "$tmp/absent.log"
check "openscad's command: SKIPPED, naming openscad" \
    grep -q "SKIPPED .*optional.md:5: openscad .*(needs openscad, not installed or not built here)" \
    "$tmp/absent.log"
check "mpirun with build/tippe: SKIPPED, naming mpirun and tippe-mpi" \
    grep -q "SKIPPED .*optional.md:8: mpirun .*(needs mpirun and tippe-mpi," "$tmp/absent.log"
check "time mpirun: SKIPPED" grep -q "SKIPPED .*optional.md:9: time mpirun" "$tmp/absent.log"
check "build/tippe-mpi after VAR=value: SKIPPED, naming tippe-mpi" \
    grep -q "SKIPPED .*optional.md:10: time OMP_NUM_THREADS=1 build/tippe-mpi .*(needs tippe-mpi," \
    "$tmp/absent.log"
# 2 blocks ran, besides the checks that blocks were found and nothing was left behind
check "the commands without optional tools ran (2 blocks and the 2 closing checks)" \
    grep -q "test_docs_commands: 4 passed, 0 failed" "$tmp/absent.log"

# The shipped docs as such a machine runs them: export.md has the openscad command.
PATH="$tmp/bare" bash "$docs_test" "$tmp/build/tippe" docs/export.md >"$tmp/export.log" 2>&1
check "docs/export.md without openscad: passes" test $? -eq 0 || sed 's/^/    /' "$tmp/export.log"
check "docs/export.md without openscad: its openscad command is said SKIPPED" \
    grep -q "SKIPPED docs/export.md:[0-9]*: openscad" "$tmp/export.log"

# --- present: the same commands run --------------------------------------------
mkdir -p "$tmp/tools"
cat >"$tmp/tools/openscad" <<'EOF'
#!/bin/sh
# stand-in: logs its arguments, writes the -o file
echo "openscad $*" >>"$TOOL_LOG"
while [ $# -gt 0 ]; do [ "$1" = -o ] && : >"$2"; shift; done
EOF
cat >"$tmp/tools/mpirun" <<'EOF'
#!/bin/sh
# stand-in: logs its arguments, runs nothing
echo "mpirun $*" >>"$TOOL_LOG"
EOF
cp "$tmp/tools/mpirun" "$tmp/build/tippe-mpi"
sed -i 's/^echo "mpirun/echo "tippe-mpi/' "$tmp/build/tippe-mpi"
chmod +x "$tmp/tools/openscad" "$tmp/tools/mpirun" "$tmp/build/tippe-mpi"
TOOL_LOG=$tmp/tools.log PATH="$tmp/tools:$tmp/bare" \
    bash "$docs_test" "$tmp/build/tippe" "$tmp/optional.md" >"$tmp/present.log" 2>&1
check "with the tools: the docs test passes" test $? -eq 0 || sed 's/^/    /' "$tmp/present.log"
check "with the tools: nothing skipped" bash -c '! grep -q SKIPPED "$1"' _ "$tmp/present.log"
check "with the tools: openscad ran on the exported file" \
    grep -q "^openscad .*-o out/printed.stl out/m12-setscrew.scad" "$tmp/tools.log"
check "with the tools: both mpirun commands ran" test "$(grep -c '^mpirun -np' "$tmp/tools.log")" -eq 2
check "with the tools: build/tippe-mpi ran" grep -q "^tippe-mpi eval" "$tmp/tools.log"

finish
