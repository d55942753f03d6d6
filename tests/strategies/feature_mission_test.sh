#!/bin/bash
# End to end: a SLEI strategy flies a short feature mission; its report.json must show features
# discovered, handed out and collected at the ground station above floors, at least one
# station-explorer meeting, and no collision or death; with several stations (gcs1, gcs2, ...),
# each one collected features.
# Usage: feature_mission_test.sh <coinspect> <config> <strategy> <min discovered> <min assigned>
#        <min collected> <scratch dir> [more options of coinspect run...]
set -euo pipefail
coinspect=$1
config=$2
strategy=$3
min_discovered=$4
min_assigned=$5
min_collected=$6
out=$7
shift 7
rm -rf "$out"
"$coinspect" run "$config" --set "strategy.name=$strategy" "$@" --quiet --out "$out" > "$out.log"
grep -E '^(features|meetings|punctuality|collisions) ' "$out.log"
# The summary's lines: "features    150: discovered D, assigned A, inspected I, collected C ...",
# "meetings    gcs-explorer G, ...", "collisions  N (deaths M)", "mission ... strategy S, ...".
count() { sed -nE "s/^$1 .*$2 ([0-9]+).*/\1/p" "$out.log"; }
used=$(sed -nE 's/^mission .*strategy ([^,]+),.*/\1/p' "$out.log")
test "$used" = "$strategy" || { echo "ran '$used', not '$strategy'"; exit 1; }
grep -qE '^collisions +0 \(deaths 0\)' "$out.log" || { echo "collisions or deaths"; exit 1; }
check() {
  local value
  value=$(count "$1" "$2")
  [[ -n "$value" && "$value" -ge "$3" ]] || { echo "$2: '$value' below $3"; exit 1; }
}
check features discovered "$min_discovered"
check features assigned "$min_assigned"
check features collected "$min_collected"
check meetings gcs-explorer 1
grep -qE '^punctuality .*on time [0-9]+, early [0-9]+, late [0-9]+, missed [0-9]+, rescheduled [0-9]+$' \
  "$out.log" || { echo "no punctuality line"; exit 1; }
for tum in "$out"/gcs*.tum; do
  station=$(basename "$tum" .tum)
  grep -q ",feature-collected,$station," "$out/events.csv" || { echo "$station collected nothing"; exit 1; }
done
echo "ok: $strategy"
