#!/bin/bash
# A run is the same on any number of threads: a short slei-b feature mission (explorers with
# LiDARs, links within 5 m, station meetings) on one and on two threads gives the same rawlog,
# byte for byte, and the same report but for its wall-clock timing; the summary and report.json
# say how many threads ran it.
# Usage: threads_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
config=$2/tests/strategies/slei-b-short.ini
out=$3
rm -rf "$out"
mkdir -p "$out"
for threads in 1 2; do
  "$coinspect" run "$config" --set mission.budget=40 --threads "$threads" --quiet \
    --out "$out/t$threads" > "$out/t$threads.log"
done
grep -Eq '^wall time +[0-9.]+ s on 1 thread$' "$out/t1.log" || { echo "no '1 thread'"; exit 1; }
grep -Eq '^wall time +[0-9.]+ s on 2 threads$' "$out/t2.log" || { echo "no '2 threads'"; exit 1; }
grep -Eq '"threads": 2,' "$out/t2/report.json" || { echo "report.json: no threads 2"; exit 1; }
# Something happened worth comparing: key frames were delivered and messages sent.
grep -Eq '^messages +sent [1-9][0-9]*, .* key frames [1-9][0-9]*, delivered [1-9]' "$out/t1.log" ||
  { echo "no messages or key frames"; grep '^messages' "$out/t1.log"; exit 1; }
cmp "$out/t1/run.rawlog" "$out/t2/run.rawlog"
cmp "$out/t1/events.csv" "$out/t2/events.csv"
# report.json: everything but "timing" (wall-clock figures).
# (two-space indent, one key per line: the block runs from '  "timing": {' to its '  }').
strip() { awk '/^  "timing": \{/ { skip = 1 } !skip { print } skip && /^  \}/ { skip = 0 }' "$1"; }
test "$(strip "$out/t1/report.json")" = "$(strip "$out/t2/report.json")" ||
  { echo "report.json differs beyond timing"; exit 1; }
echo "threads: ok"
