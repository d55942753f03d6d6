#!/usr/bin/env bash
# disk_full_test.sh <coinspect> <rawlog_status> <source dir> <scratch dir>
# Runs `coinspect run --out` under a file size limit of 300 KiB with SIGXFSZ ignored, so that
# writing run.rawlog fails with EFBIG mid-mission (as on a full disk) while the small outputs
# still fit. Expected: exit status 2, the error names run.rawlog, the mission stopped with a
# recording-failed event, summary.txt and events.csv were written, and the rawlog's prefix reads.
set -uo pipefail
coinspect=$1 status=$2 source_dir=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
out=$work/out
(
  ulimit -f 300  # KiB; the 20 s rawlog is ~2.5 MB, each other output < 40 kB
  trap '' XFSZ   # ignored signals stay ignored across exec: write() fails with EFBIG instead
  exec "$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=20 --out "$out"
) > "$work/stdout.txt" 2> "$work/stderr.txt"
code=$?
fail() { echo "FAIL: $*"; cat "$work/stderr.txt"; exit 1; }
[[ $code -eq 2 ]] || fail "exit status $code, expected 2"
grep -q "run.rawlog" "$work/stderr.txt" || fail "the error does not name run.rawlog"
grep -q "recording failed" "$work/stderr.txt" || fail "the error does not say recording failed"
for file in summary.txt events.csv score.csv report.json; do
  [[ -s "$out/$file" ]] || fail "$file missing"
done
grep -q '^[0-9.]*,recording-failed,,".*run.rawlog' "$out/events.csv" ||
  fail "events.csv has no recording-failed event naming the rawlog"
grep -q 'mission-end' "$out/events.csv" && fail "the mission should have been stopped early"
"$status" "$out/run.rawlog" > "$work/status.txt" || fail "rawlog_status could not read the header"
objects=$(awk '$1 == "objects" {print $2}' "$work/status.txt")
[[ $objects -gt 100 ]] || fail "only $objects objects read back"
grep -q '^clean 0$' "$work/status.txt" || fail "a cut rawlog should read as damaged"
grep -Eq '^status .*damage at byte offset [0-9]+' "$work/status.txt" || fail "no damage offset"
grep -Eq '^explorer1\.pose [0-9]+$' "$work/status.txt" || fail "no ground truth in the prefix"
echo "disk full: exit 2, $objects objects readable; $(grep '^status' "$work/status.txt")"
