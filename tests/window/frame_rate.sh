#!/usr/bin/env bash
# The panel's frame rate against frames counted over wall time: F2 says the figure the panel
# shows with the window's frame count and clock; pressed twice, about 3 s apart, the frames
# between over the seconds between is the measured rate, and the figure shown at the second press
# (frames in the last second) must be within 10% of it.
# usage: tests/window/frame_rate.sh EXE [FLAGS...]
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$("$here/keys.sh" "$@" -- "sleep:3" "F2=^frame rate: " "sleep:3" "F2=^frame rate: ")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
printf '%s\n' "$out" | grep '^F2: frame rate: ' | sed -E 's/.*: ([0-9.]+) fps, .* frame ([0-9]+) at ([0-9.]+) s$/\1 \2 \3/' | {
  read -r _ f1 t1
  read -r shown f2 t2
  awk -v s="$shown" -v f1="$f1" -v f2="$f2" -v t1="$t1" -v t2="$t2" 'BEGIN {
    m = (f2 - f1) / (t2 - t1)
    printf "shown %.2f fps; measured %d frames in %.3f s = %.2f fps; off by %.1f%%\n", s, f2 - f1, t2 - t1, m, 100 * (s - m) / m
    exit (s > 1.1 * m || s < 0.9 * m) ? 1 : 0
  }'
}
