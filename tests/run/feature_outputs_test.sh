#!/bin/bash
# End-to-end: a feature mission (objective = features, range links) on config/quick.ini writes a
# "features" block in report.json that agrees with itself and the clock (check_run_outputs), a
# "features" and a "meetings" line in the summary, and its feature events in events.csv.
# Usage: feature_outputs_test.sh <coinspect> <check_run_outputs> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
checker=$2
source_dir=$3
out=$4
rm -rf "$out"
# The demo paths orbit 7 m outside the building: a 10 m detector reaches it.
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 \
  --set mission.objective=features --set mission.links=range --set mission.link_range=5 \
  --set features.detect_range=10 --out "$out" > "$out.log"
"$checker" "$out" "$out.log"
line=$(grep '^features ' "$out.log") || { echo "no features line"; exit 1; }
echo "$line"
grep -q '^meetings ' "$out.log" || { echo "no meetings line"; exit 1; }
discovered=$(sed -nE 's/.*discovered ([0-9]+),.*/\1/p' <<< "$line")
test "${discovered:-0}" -gt 0 || { echo "nothing discovered"; exit 1; }
grep -q 'feature-detected' "$out/events.csv" || { echo "no feature-detected event"; exit 1; }
