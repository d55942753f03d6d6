#!/bin/bash
# End-to-end: `coinspect run` piped (not a terminal) prints one plain progress line per 10 % of
# the mission; --quiet prints none; the summary names the run mode; a bad run mode is refused.
# Usage: progress_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 > "$out/piped.log"
cat "$out/piped.log"
lines=$(grep -c '^progress ' "$out/piped.log" || true)
test "$lines" -eq 10 || { echo "expected 10 progress lines, got $lines"; exit 1; }
grep -Eq '^progress +t 2\.0 / 20\.0 s \( 10 %\), Q = [0-9.]+, detected [0-9]+ / 150, [0-9.]+x real time$' \
  "$out/piped.log" || { echo "no 10 % line"; exit 1; }
grep -Eq '^progress +t 20\.0 / 20\.0 s \(100 %\)' "$out/piped.log" || { echo "no 100 % line"; exit 1; }
if grep -q $'\r' "$out/piped.log"; then echo "carriage return in piped output"; exit 1; fi
grep -Eq '^run mode +lockstep$' "$out/piped.log" || { echo "no run mode line"; exit 1; }
# Progress lines come before the summary.
last_progress=$(grep -n '^progress ' "$out/piped.log" | tail -1 | cut -d: -f1)
score_line=$(grep -n '^score ' "$out/piped.log" | cut -d: -f1)
test "$last_progress" -lt "$score_line" || { echo "progress after the summary"; exit 1; }

"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 --quiet > "$out/quiet.log"
if grep -q '^progress ' "$out/quiet.log"; then echo "--quiet printed progress"; exit 1; fi
grep -Eq '^score +Q = [0-9]' "$out/quiet.log" || { echo "--quiet lost the summary"; exit 1; }

"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=2 --set mission.run_mode=latency \
  --quiet > "$out/latency.log"
grep -Eq '^run mode +latency: .*not deterministic' "$out/latency.log" ||
  { echo "no latency run mode line"; exit 1; }

status=0
"$coinspect" run "$source_dir/config/quick.ini" --set mission.run_mode=fast > "$out/bad.log" 2>&1 ||
  status=$?
test "$status" -eq 2 || { echo "bad run mode: status $status, expected 2"; exit 1; }
grep -q '\[mission\] run_mode' "$out/bad.log" || { echo "bad run mode: key not named"; exit 1; }
