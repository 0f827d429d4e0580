#!/usr/bin/env bash
# The Markdown of README.md and docs/*.md reads as Markdown: a paragraph that holds a link
# has balanced brackets and parentheses (outside code), so that a pasted fragment such as a
# stray "[export](export.md#split-printing))." shows up (issue 25.8), and every relative
# link's file exists. Usage: test_docs_links.sh TIPPE (unused: the docs are checked alone)
source "$(dirname "$0")/lib.sh"
setup "$@"

check "paragraphs with links are balanced and links point at files" python3 - README.md docs/*.md <<'EOF2'
import os, re, sys
bad = 0
for f in sys.argv[1:]:
    text = re.sub(r"```.*?```", "", open(f).read(), flags=re.S)
    for para in re.split(r"\n\s*\n", text):
        p = re.sub(r"`[^`]*`", "", para)
        links = re.findall(r"\]\(([^)\s]+)\)", p)
        if not links:
            continue
        for o, c in ("()", "[]"):
            depth = 0
            for ch in p:
                depth += (ch == o) - (ch == c)
                if depth < 0:
                    break
            if depth != 0:
                bad += 1
                print(f"{f}: unbalanced {o}{c} in the paragraph {para.strip()[:100]!r}...")
                break
        for target in links:
            path = target.split("#")[0]
            if path and not re.match(r"[a-z]+:", path) and \
                    not os.path.exists(os.path.join(os.path.dirname(f), path)):
                bad += 1
                print(f"{f}: link to a missing file {target}")
sys.exit(1 if bad else 0)
EOF2

finish
