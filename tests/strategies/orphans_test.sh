#!/bin/bash
# End to end: a lost explorer's inspectors are taken over by another subgroup. After the fault
# they have nothing left to do; they must report "inspecting" again late in the run (orders
# from the adopting explorer), with no collision and only the injected death.
# Usage: orphans_test.sh <coinspect> <config> <scratch dir>
set -euo pipefail
after=150 # s: the station presumes explorer1 lost at about 150 s (the config's comment)
out=$3
rm -rf "$out"
"$1" run "$2" --quiet --out "$out" > "$out.log"
grep -E '^(features|collisions) ' "$out.log"
grep -qE '^collisions +0 \(deaths 1\)' "$out.log" || { echo "collisions or other deaths"; exit 1; }
grep -qE ',death,explorer1,' "$out/events.csv" || { echo "explorer1 did not die"; exit 1; }
late=$(awk -F, -v after="$after" '$2 == "activity-changed" && ($3 == "inspector1" || $3 == "inspector2") &&
  $4 == "\"inspecting\"" && $1 > after { n++ } END { print n + 0 }' "$out/events.csv")
echo "orphans' inspecting spells after $after s: $late"
[[ "$late" -ge 1 ]] || { echo "the orphans never inspected again"; exit 1; }
echo "ok"
