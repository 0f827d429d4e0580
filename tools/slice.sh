#!/usr/bin/env bash
# Slices a design as a maker would: tippe export writes the 3MF (with tippe's per-object print
# settings), PrusaSlicer slices it headless with a shipped profile, and the G-code is left in
# OUTDIR.
#
#   tools/slice.sh DESIGN.json OUTDIR [--profile FILE.ini] [--support] [--set PATH=VALUE]...
#                  [--slicer-arg ARG]... [-- EXPORT-OPTIONS...]
#
# --profile   PrusaSlicer config (default designs/slicer/prusa-pla-0.4mm.ini)
# --support   support_material = 1 with automatic supports (the profile's threshold)
# --set       passed to tippe export (e.g. --set parts.body.print.infill=0.4)
# --slicer-arg  passed to prusa-slicer after the profile (e.g. --slicer-arg=--fill-pattern=honeycomb)
# after --    more tippe export options (e.g. --split, --clearance-mm 0)
#
# Writes OUTDIR/STEM.3mf, OUTDIR/STEM.gcode, OUTDIR/export.json (tippe export's report: the
# bodies' bounding boxes, to place the G-code back in the design's frame) and OUTDIR/slicer.log
# (PrusaSlicer's messages and its wall time). The tippe binary is $TIPPE, else build/tippe.
# PrusaSlicer runs headless (no display needed); $PRUSA_SLICER names another binary.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
header() { awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"; }
usage() { header >&2; exit 2; }
case "${1:-}" in -h|--help) header; exit 0 ;; esac
[ $# -ge 2 ] || usage
design="$1"; outdir="$2"; shift 2
profile="$here/designs/slicer/prusa-pla-0.4mm.ini"
slicer_opts=(); export_opts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --profile) [ $# -ge 2 ] || usage; profile="$2"; shift 2 ;;
    --profile=*) profile="${1#--profile=}"; shift ;;
    --support) slicer_opts+=(--support-material --support-material-auto); shift ;;
    --set) [ $# -ge 2 ] || usage; export_opts+=(--set "$2"); shift 2 ;;
    --set=*) export_opts+=(--set "${1#--set=}"); shift ;;
    --slicer-arg) [ $# -ge 2 ] || usage; slicer_opts+=("$2"); shift 2 ;;
    --slicer-arg=*) slicer_opts+=("${1#--slicer-arg=}"); shift ;;
    --) shift; export_opts+=("$@"); break ;;
    -h|--help) header; exit 0 ;;
    *) echo "slice.sh: unknown option '$1'" >&2; usage ;;
  esac
done
slicer="${PRUSA_SLICER:-prusa-slicer}"
if ! command -v "$slicer" >/dev/null 2>&1; then
  echo "slice.sh: '$slicer' not found: install PrusaSlicer, the Debian package prusa-slicer" \
       "(apt-get install --no-install-recommends prusa-slicer; Debian 12 has 2.5.0)," \
       "or set PRUSA_SLICER to its binary" >&2
  exit 3
fi
tippe="${TIPPE:-$here/build/tippe}"
[ -x "$tippe" ] || { echo "slice.sh: no tippe binary at $tippe (build first, or set TIPPE)" >&2; exit 3; }
[ -f "$design" ] || { echo "slice.sh: $design: no such design file" >&2; exit 2; }
[ -f "$profile" ] || { echo "slice.sh: $profile: no such profile" >&2; exit 2; }
mkdir -p "$outdir"
stem="$(basename "$design" .json)"
"$tippe" export "$design" -o "$outdir" --format 3mf --json "${export_opts[@]}" > "$outdir/export.json"
threemf="$outdir/$stem.3mf"
[ -f "$threemf" ] || { echo "slice.sh: tippe export wrote no $threemf" >&2; exit 1; }
start=$(date +%s.%N)
if ! "$slicer" --export-gcode --load "$profile" "${slicer_opts[@]}" -o "$outdir/$stem.gcode" \
     "$threemf" > "$outdir/slicer.log" 2>&1; then
  grep -v '\[trace\]' "$outdir/slicer.log" | tail -20 >&2
  echo "slice.sh: $slicer failed on $threemf (log: $outdir/slicer.log)" >&2
  exit 1
fi
end=$(date +%s.%N)
wall=$(echo "$end - $start" | bc)
echo "slicer wall time $wall s" >> "$outdir/slicer.log"
echo "$outdir/$stem.gcode (PrusaSlicer $wall s)"
