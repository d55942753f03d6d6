#!/usr/bin/env bash
# rawlog_edit_test.sh <write_sample_rawlog> <plugin.so> <work dir> <rawlog-edit or "">
# Records the sample run, runs MRPT's `rawlog-edit -p <plugin> --info` on it and checks that every
# sensor label appears with its count, and that all objects were read. Without the plugin,
# rawlog-edit silently stops at the first project object, so the counts prove the plugin loaded.
set -euo pipefail
writer=$1 plugin=$2 work=$3 rawlog_edit=${4:-}
if [[ -z "$rawlog_edit" || ! -x "$rawlog_edit" ]]; then
  echo "SKIPPED: rawlog-edit not installed (Debian package mrpt-apps; scripts/setup installs it)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
"$writer" "$work/run.rawlog" > "$work/expected.txt"
"$rawlog_edit" -p "$plugin" --info -i "$work/run.rawlog" > "$work/info.txt" 2>&1 || {
  cat "$work/info.txt"; echo "FAIL: rawlog-edit exited with an error"; exit 1; }

failed=0
expected_objects=1  # the run header comment
while read -r label count; do
  expected_objects=$((expected_objects + count))
  # e.g. "Sensor (Label/Occurs/Rate/Durat.) :  raffles.camera /      1 /  inf /0.000"
  if ! grep -Eq "^Sensor \(Label/Occurs/Rate/Durat\.\) : +${label//./\\.} / +${count} /" \
      "$work/info.txt"; then
    echo "FAIL: no line for label '$label' with count $count"
    failed=1
  fi
done < "$work/expected.txt"
if ! grep -Eq "^Overall number of objects +: ${expected_objects}\$" "$work/info.txt"; then
  echo "FAIL: expected 'Overall number of objects : $expected_objects'"
  failed=1
fi
if ((failed)); then
  cat "$work/info.txt"
  exit 1
fi
echo "rawlog-edit read $expected_objects objects with the expected labels and counts"
