#!/bin/bash
# End-to-end: `coinspect run config/quick.ini --out DIR` writes score.csv, one <unit>.tum per
# unit and report.json, consistent with the printed summary (checked by check_run_outputs).
# Usage: outputs_test.sh <coinspect> <check_run_outputs> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
checker=$2
source_dir=$3
out=$4
rm -rf "$out"
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 --out "$out" > "$out.log"
"$checker" "$out" "$out.log"
# Every unit of slei-b has its trajectory, the ground station included.
for unit in gcs explorer1 explorer2 inspector1 inspector2 inspector3 inspector4; do
  test -s "$out/$unit.tum" || { echo "missing $unit.tum"; exit 1; }
done
