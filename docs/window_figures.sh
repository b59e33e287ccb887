#!/usr/bin/env bash
# Screenshots of the classroom window for the docs, taken under a virtual display with keys
# pressed as a user presses them (tests/window/keys.sh): docs/figures/window/panel.png, lesson 15
# with its panel; docs/figures/window/stepped-pass.png, lesson 16 stepped to its second light's
# shadow pass, in the stencil view. The window runs in real time, so the animation's moment differs from run to run.
# usage: docs/window_figures.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
out="$root/docs/figures/window"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
cd "$work"
"$root/tests/window/keys.sh" "$build/lessons/15-robust-zfail" --time 1 --size 400x420 -- "space=^paused$" "shift+s=^saved "
"$root/tests/window/keys.sh" "$build/lessons/16-fast-robust-shadows" --time 1 --size 400x420 -- \
  "p=: ambient " "p=: shadows .light 1. " "p=: illumination .light 1. " "p=: shadows .light 2. " "Tab=^view: stencil$" "shift+s=^saved "
mv screenshot-15-robust-zfail-000.png "$out/panel.png"
mv screenshot-16-fast-robust-shadows-000.png "$out/stepped-pass.png"
echo "wrote $out/panel.png and $out/stepped-pass.png"
