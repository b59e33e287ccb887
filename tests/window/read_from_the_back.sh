#!/usr/bin/env bash
# What a class reads off the window itself, not the terminal, at --ui-scale 3 on a 1920x1080
# virtual screen (tests/window/screen_text.py measures the screenshots):
#   - Page Up at the first lesson says so on screen: between two window screenshots (shift+S) of
#     the paused lesson, one before and one after, a line of text at least 24 px high appears over
#     the top of the picture, right of the 900-px panel;
#   - the stencil legend's digits are 30 px high (10 px x the scale) in the picture's screenshot
#     (S): the picture shrinks to make the legend's room, the legend does not.
# usage: tests/window/read_from_the_back.sh EXE
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
out=$(KEYS_SH_SCREEN=1920x1080 "$here/keys.sh" "$1" --size 480x360 --ui-scale 3 -- \
  "space=^paused$" "shift+s=^saved .*-000[.]png$" "Prior=^the first lesson of the course$" "shift+s=^saved .*-001[.]png$" \
  "Tab=^view: stencil$" "s=^saved .*-002[.]png$")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
python3 "$here/screen_text.py" status screenshot-*-000.png screenshot-*-001.png 900 24 &&
  python3 "$here/screen_text.py" legend screenshot-*-002.png 30
