#!/usr/bin/env bash
# lessons/gallery: rendering one lesson leaves the others' pictures and sections in place; the page
# has a table of contents, each lesson's title, summary and page link; a variant named "stencil"
# gets colour/stencil.png and stencil/stencil.png, never stencil.stencil.png.
# usage: tests/gallery_test.sh BUILD_DIR WORK_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$1
out=$2/gallery
rm -rf "$out"
fail() { echo "gallery test: $*" >&2; exit 1; }
"$root/lessons/gallery" "$build" "$out" 00-stencil-basics 04-projected-shadows 2>/dev/null
touch -d '2000-01-01' "$out/00-stencil-basics/colour/keyhole.png"
"$root/lessons/gallery" "$build" "$out" 04-projected-shadows 2>/dev/null || fail "the second run failed"
[ -f "$out/00-stencil-basics/colour/keyhole.png" ] || fail "rendering lesson 04 removed lesson 00's pictures"
[ "$(stat -c %Y "$out/00-stencil-basics/colour/keyhole.png")" -lt 1000000000 ] ||
  fail "rendering lesson 04 rewrote lesson 00's pictures"
[ -f "$out/04-projected-shadows/stencil/stencil.png" ] || fail "no stencil/stencil.png for variant 'stencil'"
doubled=$(find "$out" -name '*.stencil.png')
[ -z "$doubled" ] || fail "doubled names: $doubled"
page=$out/index.html
grep -q '<nav><h2>Contents</h2>' "$page" || fail "no table of contents"
grep -q '<li><a href="#00-stencil-basics">00-stencil-basics: Stencil basics</a></li>' "$page" || fail "lesson 00 not in the contents"
grep -q '<li><a href="#04-projected-shadows">' "$page" || fail "lesson 04 not in the contents"
grep -q '<h2>00-stencil-basics: Stencil basics</h2>' "$page" || fail "no title for lesson 00"
grep -q 'Tag pixels in one pass' "$page" || fail "no summary for lesson 00"
link=$(grep -o 'href="[^"#]*00-stencil-basics.md"' "$page" | head -1 | sed 's/^href="//; s/"$//')
[ -n "$link" ] && [ -f "$out/$link" ] || fail "no link to lesson 00's page that leads to it ($link)"
for img in $(grep -o 'src="[^"]*"' "$page" | sed 's/^src="//; s/"$//'); do
  [ -f "$out/$img" ] || fail "the page shows $img, which is not there"
done
echo "gallery ok: $(grep -c '<figure>' "$page") figures"
