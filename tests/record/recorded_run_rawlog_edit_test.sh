#!/usr/bin/env bash
# recorded_run_rawlog_edit_test.sh <coinspect> <rawlog_status> <plugin.so> <source dir>
#                                  <scratch dir> <rawlog-edit or "">
# Records a short mission with `coinspect run --out` (a fault kills inspector4 at 2 s), then runs
# MRPT's `rawlog-edit -p <plugin> --info` on run.rawlog and checks the labels and counts it prints:
# ground truth and gimbal at 20 Hz from t = 0 (floor(20 T) + 1 each), as many captures per unit
# as the summary says, the death event, and every object (as our own reader counts them).
set -euo pipefail
coinspect=$1 status=$2 plugin=$3 source_dir=$4 work=$5 rawlog_edit=${6:-}
if [[ -z "$rawlog_edit" || ! -x "$rawlog_edit" ]]; then
  echo "SKIPPED: rawlog-edit not installed (Debian package mrpt-apps; scripts/setup installs it)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
out=$work/out
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=5 \
  --set fault.1.unit=inspector4 --set fault.1.at=2 --out "$out" > "$work/run.txt"
grep -q "^rawlog  *$out/run.rawlog\$" "$work/run.txt" || {
  cat "$work/run.txt"; echo "FAIL: the run does not say where the rawlog is"; exit 1; }
"$rawlog_edit" -p "$plugin" --info -i "$out/run.rawlog" > "$work/info.txt" 2>&1 || {
  cat "$work/info.txt"; echo "FAIL: rawlog-edit exited with an error"; exit 1; }
"$status" "$out/run.rawlog" > "$work/status.txt"
grep -q '^clean 1$' "$work/status.txt" || { cat "$work/status.txt"; echo "FAIL: not clean"; exit 1; }

failed=0
expect() {  # expect <label> <count>
  if ! grep -Eq "^Sensor \(Label/Occurs/Rate/Durat\.\) : +${1//./\\.} / +${2} /" "$work/info.txt"; then
    echo "FAIL: rawlog-edit has no line for label '$1' with count $2"
    failed=1
  fi
}
sim_time=$(awk '$1 == "sim" && $2 == "time" {print $3}' "$work/run.txt")
samples=$(awk -v t="$sim_time" 'BEGIN {print int(t * 20 + 1e-6) + 1}')
for unit in gcs explorer1 explorer2 inspector1 inspector2 inspector3 inspector4; do
  expect "$unit.pose" "$samples"
  expect "$unit.imu" "$samples"
  [[ $unit == gcs ]] && continue
  expect "$unit.gimbal" "$samples"
  captures=$(awk -v u="$unit" '$1 == u {print $5}' "$work/run.txt")
  expect "$unit.camera" "$captures"
done
expect inspector4.event 2  # the fault and the death
grep -Eq '^Sensor \(Label/Occurs/Rate/Durat\.\) : +explorer1\.lidar / +[1-9]' "$work/info.txt" || {
  echo "FAIL: no explorer1.lidar"; failed=1; }
# Every label and count our reader sees, rawlog-edit sees too; and the same total.
while read -r label count; do
  case $label in objects | clean | status) continue ;; esac
  expect "$label" "$count"
done < "$work/status.txt"
objects=$(awk '$1 == "objects" {print $2}' "$work/status.txt")
grep -Eq "^Overall number of objects +: ${objects}\$" "$work/info.txt" || {
  echo "FAIL: expected 'Overall number of objects : $objects'"; failed=1; }
if ((failed)); then
  cat "$work/run.txt" "$work/info.txt"
  exit 1
fi
echo "rawlog-edit read $objects objects of a recorded run with the expected labels and counts"
