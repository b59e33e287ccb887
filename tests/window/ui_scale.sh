#!/usr/bin/env bash
# The panel read from the back of a classroom: at --ui-scale 2 in a 1280x720 window on a
# 1920x1080 virtual screen, the window's own screenshot (shift+S, the panel too) is measured:
# the panel's text lines at least 24 px high, none reaching the window's bottom edge, and the
# window says its panel fits, cuts nothing and lists the keys in full.
# usage: tests/window/ui_scale.sh EXE
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# --size is the picture: the window is it plus the panel, 300 px x the UI scale.
out=$(KEYS_SH_SCREEN=1920x1080 "$here/keys.sh" "$1" --size 680x720 --ui-scale 2 -- \
  "space=^panel shown: the picture is 680x720 beside it, from x = 600; window 1280x720 at [-0-9]+,[-0-9]+; ui scale 2, text 26 px; the panel fits [(][0-9]+ of 720 px[)]; the keys listed$" \
  "shift+s=^saved ")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
shot=$(ls screenshot-*.png)
python3 "$here/measure_panel.py" "$shot" 600 24
