#!/usr/bin/env bash
# A section opened by a click keeps the panel in the window: at --ui-scale 2 on a 1920x1080 virtual
# screen, a click on a folded section's header at X,Y opens it, the window says its panel then
# fits, the keys LISTED or folded, and in the window's screenshot (shift+S) no panel text reaches
# its bottom edge (tests/window/measure_panel.py: lines at least 24 px high, none in the last 8 rows).
# usage: tests/window/section_fits.sh EXE WxH X,Y LISTED  (WxH: --size, the picture beside the
# 600-px panel; LISTED: listed or folded)
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
out=$(KEYS_SH_SCREEN=1920x1080 "$here/keys.sh" "$1" --size "$2" --ui-scale 2 -- "wait=^panel shown: " \
  "click:$3=^the (keys listed|draw calls and counts shown)$" \
  "wait=^panel shown: .*; the panel fits [(][0-9]+ of ${2#*x} px[)].*; the keys $4$" "shift+s=^saved ")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
python3 "$here/measure_panel.py" "$(ls screenshot-*.png)" 600 24
