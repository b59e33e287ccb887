#!/usr/bin/env bash
# Stepping through the passes holds the animation: the window says the same time after every step
# (tests/window/keys.sh presses P four times, a fraction of a second apart at least).
# usage: tests/window/stepping_holds_time.sh EXE
set -uo pipefail
out=$("$(dirname "$0")/keys.sh" "$1" -- "p=^after pass 1 " "p=^after pass 2 " "p=^after pass 3 " "p=^after pass 4 ")
code=$?
[ "$code" -eq 0 ] || exit "$code"
echo "$out"
times=$(printf '%s\n' "$out" | grep -o 't = [0-9.]* s, held' | sort -u)
[ "$(printf '%s\n' "$out" | grep -c 't = ')" -eq 4 ] || { echo "not four steps with a time" >&2; exit 1; }
[ "$(printf '%s\n' "$times" | wc -l)" -eq 1 ] || { echo "time moved while stepping: $times" >&2; exit 1; }
