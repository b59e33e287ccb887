#!/usr/bin/env bash
# A slider's text beside its grab, not over it: tests/window/keys.sh drives the lesson (its flags
# and steps as given), then the window's own screenshot (shift+S, the panel too) is checked with
# grab_clear.py over the panel's PANEL_WIDTH columns.
# usage: tests/window/slider_text.sh PANEL_WIDTH EXE [FLAGS...] -- KEY=REGEX...
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
panel=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$here/keys.sh" "$@" "shift+s=^saved "
code=$?
[ "$code" -eq 0 ] || exit "$code"
python3 "$here/grab_clear.py" screenshot-*.png "$panel"
