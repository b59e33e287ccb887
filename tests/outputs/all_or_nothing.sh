#!/usr/bin/env bash
# A run's outputs are one transaction (gl/image.h's OutputSet): a write that fails part way leaves
# none of the run's files, a planted link is never followed, and a killed run leaves nothing named.
# Writes fail by a file-size limit (prlimit --fsize; SIGXFSZ ignored, so a write past it fails with
# EFBIG, as on a full disk) that lets the small files through and stops a larger one.
# usage: tests/outputs/all_or_nothing.sh BUILD_DIR WORK_DIR CASE
#   cases: passes, out-and-passes, masks, shadow-hours, golden-artifacts, long-name, planted-link, killed
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$1
case_name=$3
work=$2/$case_name
lessons=$build/lessons
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "all-or-nothing $case_name: $*" >&2; exit 1; }
trap '' XFSZ  # inherited: a write past the limit fails with EFBIG instead of killing the run

# run_limited BYTES CMD...: runs CMD with files limited to BYTES; prints its exit code and stderr.
run_limited() {
  local bytes=$1
  shift
  prlimit --fsize="$bytes" -- "$@" >stdout.log 2>stderr.log
  echo $?
}
# Nothing the run could have written: only this script's logs in the folder, no folder left.
expect_nothing() {
  local left
  left=$(find . -mindepth 1 -not -name '*.log' -not -name 'victim.txt' | sort)
  [ -z "$left" ] || fail "left behind: $left ($(tail -1 stderr.log))"
}
expect_one_line() {
  [ "$(wc -l <stderr.log)" -eq 1 ] || fail "expected one line on stderr, got: $(cat stderr.log)"
  grep -q "$1" stderr.log || fail "expected '$1' on stderr, got: $(cat stderr.log)"
}

case $case_name in
  passes)  # lesson 14's pass pictures: 3-6 KB ones fit, the 9 KB ones do not
    code=$(run_limited 8000 "$lessons/14-csg" --headless --quiet --size 320x240 --passes P)
    [ "$code" = 2 ] || fail "expected exit 2, got $code: $(cat stderr.log)"
    expect_one_line "could not write P/.*File too large"
    expect_nothing ;;
  out-and-passes)
    code=$(run_limited 8000 "$lessons/13-depth-complexity" --headless --quiet --size 320x240 --out a.png --passes P)
    [ "$code" = 2 ] || fail "expected exit 2, got $code: $(cat stderr.log)"
    expect_one_line "could not write .*File too large"
    expect_nothing ;;
  masks)  # lesson 16 stages one mask per light while it renders (16 lights, ~1.2 KB each), then --out (~23 KB)
    printf 'camera eye 0 6 9 target 0 0.5 0 near 0.3\n' >s.scene
    for i in $(seq 0 15); do echo "light point $((i % 4 - 2)) 5 $((i / 4 - 2)) color 0.1 0.1 0.1" >>s.scene; done
    printf 'object g plane half 5\n  casts no\nobject a sphere\n  translate 0 1 0\nobject b box\n  translate 1.5 0.5 0\n' >>s.scene
    mv s.scene ../masks.scene
    code=$(run_limited 5000 "$lessons/16-fast-robust-shadows" --headless --quiet --size 320x240 --scene ../masks.scene --mask-out m --out a.png)
    [ "$code" = 2 ] || fail "expected exit 2, got $code: $(cat stderr.log)"
    expect_one_line "could not write .*File too large"
    expect_nothing ;;
  shadow-hours)  # the profile and its raw counts: the raw one is small, the picture not
    code=$(run_limited 3000 "$lessons/15-robust-zfail" --headless --quiet --size 320x240 \
           --scene "$root/tests/scenes/sun-box-building.scene" --shadow-hours h.png --shadow-span 9:00-12:00 --mask-out m)
    [ "$code" = 2 ] || fail "expected exit 2, got $code: $(cat stderr.log)"
    expect_one_line "could not write .*File too large"
    expect_nothing ;;
  golden-artifacts)  # a failed comparison is exit 1 whether or not its pictures can be written
    "$lessons/00-stencil-basics" --headless --quiet --size 320x240 --variant ops --golden g --update-golden 2>/dev/null ||
      fail "could not write a golden"
    mv g/ops.png g/keyhole.png && mv g/ops.stencil.png g/keyhole.stencil.png
    code=$(run_limited 2000 "$lessons/00-stencil-basics" --headless --quiet --size 320x240 --variant keyhole --golden g --artifacts art)
    [ "$code" = 1 ] || fail "expected exit 1 (the golden failed), got $code: $(cat stderr.log)"
    expect_one_line "golden FAILED: .*its images were not written: could not write art/.*File too large"
    [ ! -e art ] || fail "left behind: $(find art)"
    code=$(run_limited unlimited "$lessons/00-stencil-basics" --headless --quiet --size 320x240 --variant keyhole --golden g --artifacts art)
    [ "$code" = 1 ] && [ -f art/summary.json ] && [ -f art/colour-diff.png ] || fail "unlimited: exit $code, no artifacts"
    ;;
  long-name)  # 250 bytes: within NAME_MAX, and the temporary names do not lengthen it
    name=$(printf 'n%.0s' $(seq 246)).png
    "$lessons/00-stencil-basics" --headless --quiet --size 64x48 --out "$name" --stencil-out s.png 2>stderr.log ||
      fail "a 250-byte name failed: $(cat stderr.log)"
    [ "$(find . -mindepth 1 -not -name '*.log' | wc -l)" = 3 ] && [ -f "$name" ] || fail "expected 3 files: $(ls -A)"
    ;;
  planted-link)  # a link and a folder at the old guessable temporary names, a link at an output
    echo "victim" >victim.txt
    bash -c 'ln -s victim.txt a.png.tmp-$$ && mkdir b.png.tmp-$$ && ln -s victim.txt b.png &&
             exec "$0" --headless --quiet --size 64x48 --out a.png --stencil-out b.png' "$lessons/13-depth-complexity" 2>stderr.log ||
      fail "the run failed: $(cat stderr.log)"
    [ "$(cat victim.txt)" = victim ] || fail "a planted link was followed: victim.txt changed"
    [ -f a.png ] && [ ! -L a.png ] && [ -f b.png ] && [ ! -L b.png ] && [ -f b.raw.png ] ||
      fail "expected a.png, b.png and b.raw.png as files: $(ls -lA)"
    [ "$(find . -mindepth 1 -name '*.tmp-*' | wc -l)" = 2 ] || fail "the planted names were touched: $(ls -lA)"
    ;;
  killed)  # SIGKILL and SIGTERM at moments through a large write leave the whole file or nothing
    for signal in KILL TERM; do
      for delay in 0.2 0.5 0.8 1.1 1.4 1.7 2.0 2.5; do
        "$lessons/00-stencil-basics" --headless --quiet --size 4096x4096 --out big.png --stencil-out big-s.png 2>/dev/null &
        pid=$!
        sleep "$delay"
        kill -s "$signal" "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        left=$(find . -mindepth 1 -not -name '*.log' -not -name 'big.png' -not -name 'big-s.png' -not -name 'big-s.raw.png')
        [ -z "$left" ] || fail "SIG$signal after ${delay}s left: $left"
        if [ -e big.png ] || [ -e big-s.png ] || [ -e big-s.raw.png ]; then
          [ -f big.png ] && [ -f big-s.png ] && [ -f big-s.raw.png ] || fail "SIG$signal after ${delay}s left part of the set: $(ls)"
          python3 -c "import sys; d=open('big.png','rb').read(); sys.exit(0 if d.endswith(b'IEND\xaeB\x60\x82') else 1)" ||
            fail "SIG$signal after ${delay}s left a partial big.png"
        fi
        rm -f big.png big-s.png big-s.raw.png
      done
    done ;;
  *) fail "unknown case" ;;
esac
echo "all-or-nothing $case_name: ok"
