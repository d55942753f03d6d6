#!/usr/bin/env bash
# killed_run_test.sh <coinspect> <rawlog_status> <source dir> <scratch dir>
# Starts a long recorded mission, waits until run.rawlog has grown past a few flushes (1 s of
# simulated time each, ~130 kB), kills it with SIGKILL and checks that the prefix reads back up
# to the damage, which is reported with the object count and byte offsets.
set -uo pipefail
coinspect=$1 status=$2 source_dir=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
out=$work/out
"$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=600 --out "$out" \
  > "$work/stdout.txt" 2>&1 &
pid=$!
fail() { echo "FAIL: $*"; kill -9 "$pid" 2> /dev/null; exit 1; }
size=0
for _ in $(seq 1 200); do  # at most 20 s
  size=$(stat -c %s "$out/run.rawlog" 2> /dev/null || echo 0)
  ((size > 600000)) && break
  kill -0 "$pid" 2> /dev/null || fail "the run ended before it could be killed"
  sleep 0.1
done
((size > 600000)) || fail "run.rawlog did not grow past 600 kB"
kill -9 "$pid"
wait "$pid" 2> /dev/null
"$status" "$out/run.rawlog" > "$work/status.txt" || fail "rawlog_status could not read the header"
objects=$(awk '$1 == "objects" {print $2}' "$work/status.txt")
[[ $objects -gt 1000 ]] || fail "only $objects objects read back from $size bytes"
grep -q '^clean 0$' "$work/status.txt" || fail "a killed run has no gzip trailer: damaged"
grep -Eq "^status .*: $objects objects read, damage at byte offset [0-9]+ \(decompressed stream; compressed offset [0-9]+\)" \
  "$work/status.txt" || fail "no damage message with the object count and offsets"
grep -Eq '^explorer1\.lidar [0-9]+$' "$work/status.txt" || fail "no LiDAR in the prefix"
echo "killed at $size bytes: $objects objects readable; $(grep '^status' "$work/status.txt")"
