#!/usr/bin/env bash
# The panel's frame rate against frames counted over wall time. The window writes each frame's
# end time ($STENCIL_FRAME_LOG); F2 says the figure the panel shows, with the window's clock. Once the
# lesson has run 3 s, at each of two presses a second apart this script counts from the log the
# frame intervals of the last second before the press (the last frame ended, back to the last end
# a second or more before it) over their time, and the figure shown must be within 10% of it.
# usage: tests/window/frame_rate.sh EXE [FLAGS...]
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
log=$(mktemp)
trap 'rm -f "$log"' EXIT
out=$(STENCIL_FRAME_LOG=$log "$here/keys.sh" "$@" -- "sleep:3" "F2=^frame rate: " "sleep:1" "F2=^frame rate: ")
code=$?
echo "$out"
[ "$code" -eq 0 ] || exit "$code"
bad=0
while read -r shown clock; do
  awk -v s="$shown" -v now="$clock" '
    { t[n++] = $1 }
    END {
      # Frame ends up to the press; the first kept is the last one a second or more before the last.
      last = -1; for (i = 0; i < n; ++i) if (t[i] <= now) last = i
      first = last; while (first > 0 && t[first] > t[last] - 1) --first
      m = (last - first) / (t[last] - t[first])
      printf "shown %.2f fps at %.6f s; counted %d frames in %.3f s = %.2f fps; off by %.1f%%\n", s, now, last - first, t[last] - t[first], m, 100 * (s - m) / m
      exit (s > 1.1 * m || s < 0.9 * m) ? 1 : 0
    }' "$log" || bad=1
done < <(printf '%s\n' "$out" | grep '^F2: frame rate: ' | sed -E "s/.*: ([0-9.]+) fps, .* frame [0-9]+ at ([0-9.]+) s on the window's clock; .*\$/\\1 \\2/")
exit "$bad"
