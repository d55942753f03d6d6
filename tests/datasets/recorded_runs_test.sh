#!/usr/bin/env bash
# Every recorded mission in datasets/runs/ still reads and re-scores to its expected score:
# rawlogs written by earlier versions must keep reading (doc/datasets.md).
set -euo pipefail
coinspect="$1"
runs="$2"
count=0
for folder in "$runs"/*/; do
  name=$(basename "$folder")
  expected=$(cat "$folder/expected_score.txt")
  output=$("$coinspect" eval "$folder/run.rawlog" 2>&1) ||
    { echo "$output"; echo "datasets/runs/$name: coinspect eval failed"; exit 1; }
  rescored=$(sed -n 's/^re-scored *//p' <<<"$output")
  [[ "$rescored" == "$expected: equal" ]] ||
    { echo "$output"; echo "datasets/runs/$name: re-scored '$rescored', expected '$expected: equal'"; exit 1; }
  echo "datasets/runs/$name: $rescored"
  count=$((count + 1))
done
((count >= 2)) || { echo "expected at least 2 recorded runs in $runs, found $count"; exit 1; }
