#!/usr/bin/env bash
# What a class reads off the window itself, not the terminal, at --ui-scale 3 on a 1920x1080
# virtual screen (tests/window/screen_text.py measures the screenshots):
#   - Page Up at the first lesson says so on screen: between two window screenshots (shift+S) of
#     the paused lesson, one before and one after, a line of text at least 24 px high appears over
#     the top of the picture, right of the 900-px panel;
#   - the stencil legend's digits are 40 px high (the panel's 13 px text x the scale, in 5 dots of
#     8 px) in the picture's screenshot (S): the picture shrinks to make the legend's room;
#   - with the panel hidden (F1), Page Down's lesson names itself on screen: a line at least 24 px
#     high over the paused picture in the screenshot just after it opens, gone from one taken 7 s later.
# usage: tests/window/read_from_the_back.sh EXE
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
out=$(KEYS_SH_SCREEN=1920x1080 "$here/keys.sh" "$1" --size 480x360 --ui-scale 3 -- \
  "space=^paused$" "shift+s=^saved .*-000[.]png$" "Prior=^the first lesson of the course$" "shift+s=^saved .*-001[.]png$" \
  "Tab=^view: stencil$" "s=^saved .*-002[.]png$" \
  "F1=^panel hidden" "Next=^lesson 01-[a-z-]+: " "space=^paused$" "shift+s=^saved .*01-[a-z-]+-000[.]png$" "sleep:7" \
  "shift+s=^saved .*01-[a-z-]+-001[.]png$")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
python3 "$here/screen_text.py" status screenshot-00-*-000.png screenshot-00-*-001.png 900 24 &&
  python3 "$here/screen_text.py" legend screenshot-00-*-002.png 40 &&
  python3 "$here/screen_text.py" status screenshot-01-*-001.png screenshot-01-*-000.png 0 24
