#!/bin/bash
# End-to-end: `coinspect run config/quick.ini` flies the short mission and prints its summary.
# Usage: run_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
rm -rf "$out"
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 --out "$out" > "$out.log"
cat "$out.log"
for line in '^score +Q = [0-9]' '^detected +[0-9]+ / 150 ' '^collisions +0 \(deaths 0\)' \
            '^distance ' '^real-time factor [0-9.]+x' '^clock +started at'; do
  grep -Eq "$line" "$out.log" || { echo "missing summary line: $line"; exit 1; }
done
# Something was scored: Q > 0.
grep -Eq '^score +Q = ([1-9][0-9]*\.[0-9]+|0\.[0-9]*[1-9])' "$out.log" || { echo "Q is 0"; exit 1; }
test -s "$out/summary.txt"
grep -q '^time,kind,unit,detail' "$out/events.csv"
grep -q 'mission-end' "$out/events.csv"
