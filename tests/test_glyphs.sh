#!/usr/bin/env bash
# Every glyph of every label of every shipped design's drawings is in the font cairo draws
# them with (issue 25.4: the diameter sign U+2300 was an empty box in PNG and PDF on a
# machine whose sans-serif, Noto Sans, lacks it): the build sheet's SVG (cairo's glyph
# outlines: none is the font's .notdef box) and the section drawing's SVG labels (each
# character in the charset of fontconfig's sans-serif and sans-serif:bold, by fc-query).
# Usage: test_glyphs.sh TIPPE
source "$(dirname "$0")/lib.sh"
setup "$@"

fonts=()
if command -v fc-match >/dev/null && command -v fc-query >/dev/null; then
    for pat in sans-serif sans-serif:bold; do
        fonts+=("$(fc-match -f '%{file}' "$pat")")
    done
else
    echo "fc-match or fc-query missing: the section's labels are checked on the sheet only"
fi

for f in designs/*.json; do
    python3 -c 'import json,sys; sys.exit(0 if "parts" in json.load(open(sys.argv[1])) else 1)' "$f" || continue
    stem=$(basename "$f" .json)
    if ! "$tippe" build "$f" -o "$tmp/$stem" >/dev/null 2>"$tmp/$stem.err"; then
        bad "$stem: build failed: $(cat "$tmp/$stem.err")"
        continue
    fi
    check "$stem: no glyph of the sheet is the font's missing-glyph box" \
        python3 tests/glyphs.py sheet "$tmp/$stem/$stem-sheet.svg"
    for font in "${fonts[@]}"; do
        check "$stem: every character of the section's labels is in $(basename "$font")" \
            python3 tests/glyphs.py labels "$font" "$tmp/$stem/$stem-section.svg"
    done
done
# the check itself: a label with U+2300 is caught where the font lacks it
if [ ${#fonts[@]} -gt 0 ] && ! fc-query -f '%{charset}\n' "${fonts[0]}" | python3 -c '
import sys
have = set()
for r in sys.stdin.read().split():
    a, _, b = r.partition("-"); have.update(range(int(a, 16), int(b or a, 16) + 1))
sys.exit(0 if 0x2300 in have else 1)'; then
    printf '<svg><text x="0">\xe2\x8c\x8011 screw</text></svg>\n' >"$tmp/box.svg"
    check "the label check catches a character the font lacks" \
        test "$(python3 tests/glyphs.py labels "${fonts[0]}" "$tmp/box.svg" >/dev/null; echo $?)" = 1
fi

finish
