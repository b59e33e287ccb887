#!/usr/bin/env bash
# Drives a lesson's window as a user does: opens it on a virtual display (xvfb-run), presses
# keys with xdotool and waits, after each, for the line the window says on stderr.
# usage: tests/window/keys.sh EXE [FLAGS...] -- KEY=REGEX...
#   KEY    an xdotool key name (Tab, v, p, shift+p, Escape); or size:WxH or move:X,Y, which resize
#          or move the window as a user's window manager would (xdotool windowsize, windowmove);
#          or sleep:SECONDS, a pause (no REGEX); or click:X,Y or ctrlclick:X,Y, a click or a
#          ctrl+click in the window at X,Y; or wait, no input: only the line to wait for (a key
#          pressed just to wait, even shift, can be held down when the next click arrives: ImGui
#          ignores a click on a header with a modifier down)
#   REGEX  an extended regular expression that a line the window says after the key must match,
#          within 10 s; the next step looks only at the lines after that one. Empty: no line wanted.
# After the steps one Escape must close the window within 10 s.
# Exit 0: every step did; 1: one did not (named on stderr); 77: no xvfb-run, xdotool or window.
set -uo pipefail
if [ -z "${KEYS_SH_DISPLAY:-}" ]; then
  command -v xvfb-run >/dev/null || { echo "xvfb-run is not installed (apt-get install xvfb xauth): skipped"; exit 77; }
  command -v xdotool >/dev/null || { echo "xdotool is not installed (apt-get install xdotool): skipped"; exit 77; }
  # KEYS_SH_SCREEN: the virtual screen's size (a projector's 1920x1080 for the UI scale's test).
  KEYS_SH_DISPLAY=1 exec xvfb-run -a -s "-screen 0 ${KEYS_SH_SCREEN:-1024x768}x24" "$0" "$@"
fi

exe=$1
shift
flags=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do flags+=("$1"); shift; done
[ $# -gt 0 ] && shift
log=$(mktemp)
trap 'rm -f "$log"; [ -n "${pid:-}" ] && kill "$pid" 2>/dev/null' EXIT

"$exe" --backend window "${flags[@]}" 2>"$log" &
pid=$!
wid=""
for _ in $(seq 100); do
  wid=$(xdotool search --onlyvisible --pid "$pid" 2>/dev/null | head -1)
  [ -n "$wid" ] && break
  if ! kill -0 "$pid" 2>/dev/null; then
    wait "$pid"
    code=$?
    cat "$log" >&2
    [ "$code" -eq 77 ] && { echo "no window on the virtual display: skipped"; exit 77; }
    echo "the lesson exited ($code) before its window showed" >&2
    exit 1
  fi
  sleep 0.1
done
[ -n "$wid" ] || { cat "$log" >&2; echo "no window appeared in 10 s" >&2; exit 1; }
xdotool windowfocus --sync "$wid"
sleep 0.5

seen=0  # lines of the log already matched
for step in "$@"; do
  key=${step%%=*}
  want=${step#*=}
  # The next lesson of the course replaces the program (same process) with a window of its own.
  now=""
  for _ in $(seq 100); do
    now=$(xdotool search --onlyvisible --pid "$pid" 2>/dev/null | head -1)
    [ -n "$now" ] && break
    sleep 0.1
  done
  if [ -n "$now" ] && [ "$now" != "$wid" ]; then
    wid=$now
    xdotool windowfocus --sync "$wid"
    sleep 0.5
  fi
  case "$key" in
    size:*) size=${key#size:}; xdotool windowsize "$wid" "${size%x*}" "${size#*x}" ;;
    move:*) at=${key#move:}; xdotool windowmove "$wid" "${at%,*}" "${at#*,}" ;;
    sleep:*) sleep "${key#sleep:}"; continue ;;
    wait) ;;
    click:*) at=${key#click:}; xdotool mousemove --window "$wid" "${at%,*}" "${at#*,}" click 1 ;;
    ctrlclick:*)  # ctrl+click at X,Y in the window: ImGui's way into a slider's typed value
      at=${key#ctrlclick:}
      xdotool mousemove --window "$wid" "${at%,*}" "${at#*,}" keydown ctrl click 1 keyup ctrl ;;
    *) xdotool key --clearmodifiers "$key" ;;
  esac
  [ -z "$want" ] && { sleep 0.3; continue; }
  found=""
  for _ in $(seq 100); do
    found=$(tail -n +"$((seen + 1))" "$log" | grep -n -E -m1 -- "$want" | cut -d: -f1)
    [ -n "$found" ] && break
    sleep 0.1
  done
  if [ -z "$found" ]; then
    echo "after key $key: no line matching '$want' in 10 s; the window said:" >&2
    cat "$log" >&2
    exit 1
  fi
  seen=$((seen + found))
  echo "$key: $(sed -n "${seen}p" "$log")"
done

xdotool key --clearmodifiers Escape
for _ in $(seq 100); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then
  echo "one Escape did not close the window in 10 s" >&2
  exit 1
fi
wait "$pid"
code=$?
pid=""
[ "$code" -eq 0 ] || { cat "$log" >&2; echo "the lesson exited with $code" >&2; exit 1; }
echo "Escape: closed"
