#!/usr/bin/env bash
# Runs the same commands with two builds of tippe and says whether every output is
# byte-identical: for a change that must not change behaviour (a restructure, a
# rename). The commands are every `build/tippe ...` command shown in README.md and
# docs/*.md, and eval, classify, sweep, check, export and build of every shipped
# design, each with and without --json. Each run happens in a scratch folder of its
# own (build -> the build's folder, designs -> this checkout's designs), so the two
# runs differ only by the binary; their stdout, stderr, exit status and every file
# they write are compared. Lines that state a time taken ("took", "ms", "s left")
# and PDF creation dates are dropped first, since they change from run to run.
#
# Usage: tools/same_output.sh OLD_BUILD_DIR NEW_BUILD_DIR
# Exit 0 when everything matches; otherwise the differing files are listed (KEEP=1
# keeps the scratch folders to look at).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR" >&2; exit 2; }
repo=$(cd "$(dirname "$0")/.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
work=$(mktemp -d)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$work"' EXIT

# The command list, once, for both runs.
{
    python3 - "$repo" <<'EOF'
import re, sys, glob, os
repo = sys.argv[1]
for path in [os.path.join(repo, "README.md")] + sorted(glob.glob(os.path.join(repo, "docs", "*.md"))):
    lines = open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        if line.startswith("build/tippe ") and "tippe-mpi" not in line:
            cmd = line
            while cmd.endswith("\\") and i + 1 < len(lines):
                i += 1
                cmd = cmd[:-1] + " " + lines[i].strip()
            print(cmd)
        i += 1
EOF
    for d in "$repo"/designs/*.json; do
        name=designs/$(basename "$d")
        case "$name" in designs/materials.json|designs/catalogue.json) continue ;; esac
        for json in "" "--json"; do
            echo "build/tippe eval $name --z2 5 $json"
            echo "build/tippe classify $name --z2 5 $json"
            echo "build/tippe sweep $name $json"
            echo "build/tippe check $name --z2 5 $json"
        done
        echo "build/tippe export $name -o out/export-$(basename "$d" .json)"
        echo "build/tippe build $name -o out/build-$(basename "$d" .json)"
    done
} | awk '!seen[$0]++' > "$work/commands"

run_all() { # BUILD_DIR SCRATCH
    local scratch=$2 k=0
    mkdir -p "$scratch/out" "$scratch/docs/img" "$scratch/res"
    ln -s "$1" "$scratch/build"
    cp -r "$repo/designs" "$scratch/designs" # some examples write into designs/
    ln -s "$repo/tools" "$scratch/tools"
    while IFS= read -r cmd; do
        k=$((k + 1))
        (cd "$scratch" && OMP_NUM_THREADS=2 bash -c "$cmd" > "res/$k.out" 2> "res/$k.err" \
            < /dev/null; echo "$?" > "res/$k.rc") || true
        echo "$cmd" > "$scratch/res/$k.cmd"
    done < "$work/commands"
}
echo "same_output: $(wc -l < "$work/commands") commands, each with $old and $new" >&2
run_all "$old" "$work/a"
run_all "$new" "$work/b"

# Times change from run to run: mask them (the same way in both runs). A 3MF
# is a zip whose entries carry the time they were written: compare its entries'
# contents instead.
normalise() {
    find "$1" -type f \( -name '*.out' -o -name '*.err' -o -name '*.md' -o -name '*.json' \
        -o -name '*.csv' -o -name '*.txt' -o -name '*.scad' \) -print0 |
        xargs -0 -r sed -i -E 's/(evaluations|took|in|elapsed)(,? )[0-9.e+-]+ ?m?s\b/\1\2T/g;
            s/[0-9.]+ s on /T s on /g; s/[0-9.]+ (launches|cells|candidates)\/s/T \1\/s/g;
            s/^(time +)[0-9.e+-]+ s/\1T s/; s/"(elapsed_s|seconds)": *[0-9.e+-]+/"\1": T/g;
            /s left|CreationDate|ModDate/d'
    find "$1" -type f -name '*.3mf' -print0 | while IFS= read -r -d '' f; do
        python3 -c 'import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
for n in sorted(z.namelist()):
    sys.stdout.buffer.write(n.encode() + b"\n" + z.read(n))' "$f" > "$f.entries" && rm "$f"
    done
    # 3MF objects get random UUIDs, PDFs the time they were made.
    find "$1" -type f \( -name '*.entries' -o -name '*.pdf' \) -print0 |
        LC_ALL=C xargs -0 -r sed -i -E 's/UUID="[0-9a-f-]+"/UUID="U"/g; s/\(D:[0-9]+Z\)/(D)/g'
    find "$1" -maxdepth 1 -type l -delete
}
normalise "$work/a"
normalise "$work/b"
if diff -rq --no-dereference "$work/a" "$work/b" > "$work/diff"; then
    echo "same_output: all outputs identical"
else
    echo "same_output: outputs differ:"
    while read -r _ a _ b _; do
        case "$a" in *.out|*.err|*.rc)
            k=$(basename "$a"); k=${k%.*}
            echo "  $(cat "$work/a/res/$k.cmd") ($(basename "$a"))" ;;
        *) echo "  $a" ;; esac
    done < "$work/diff"
    exit 1
fi
