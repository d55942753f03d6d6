#!/bin/bash
# End to end: one strategy flies a short whole mission; its report.json must show a score above
# a floor and no collision, no death.
# Usage: whole_mission_test.sh <coinspect> <config> <strategy> <min score> <scratch dir>
set -euo pipefail
coinspect=$1
config=$2
strategy=$3
min_score=$4
out=$5
rm -rf "$out"
"$coinspect" run "$config" --set "strategy.name=$strategy" --quiet --out "$out" > "$out.log"
cat "$out.log"
report="$out/report.json"
# Top-level keys of report.json are indented by two spaces (nested ones by more).
value() { sed -nE "s/^  \"$1\": ([-0-9.eE+]+),?$/\1/p" "$report"; }
score=$(value score)
collisions=$(value collisions)
deaths=$(value deaths)
strategy_used=$(sed -nE 's/^  "strategy": "([^"]*)",?$/\1/p' "$report")
echo "strategy $strategy_used, score $score, collisions $collisions, deaths $deaths"
test "$strategy_used" = "$strategy" || { echo "ran '$strategy_used', not '$strategy'"; exit 1; }
test "$collisions" = 0 || { echo "collisions: $collisions"; exit 1; }
test "$deaths" = 0 || { echo "deaths: $deaths"; exit 1; }
awk -v s="$score" -v m="$min_score" 'BEGIN { exit !(s + 0 >= m + 0) }' ||
  { echo "score $score below $min_score"; exit 1; }
