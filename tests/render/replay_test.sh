#!/bin/bash
# End-to-end: `coinspect replay` of a short recorded mission prints the events as they happen and
# writes floor(end * fps) + 1 frames of the requested size, 000000.png first; a chase view of a
# unit works, of an unknown unit exits 2 naming the units.
# Usage: replay_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
source "$(dirname "$0")/../record_short_run.sh"
record_short_run "$coinspect" "$source_dir" "$out" 4

"$coinspect" replay "$out/run/run.rawlog" --fps 2 --size 160x120 --out "$out/overview" \
  > "$out/replay.log" 2> "$out/replay.err"
cat "$out/replay.log"
# Events: time, kind, unit, detail, with events.csv's kind names; the mission's start and end
# are among them.
grep -Eq '^ +[0-9]+\.[0-9]{3} s  mission-start ' "$out/replay.log" || { echo "no start event"; exit 1; }
grep -Eq '^ +[0-9]+\.[0-9]{3} s  mission-end ' "$out/replay.log" || { echo "no end event"; exit 1; }
end=$(sed -nE 's/^frames +[0-9]+ at 2 fps for t = 0 to ([0-9.]+) s .*/\1/p' "$out/replay.log")
[[ -n $end ]] || { echo "no frames line"; exit 1; }
expected=$(awk -v t="$end" 'BEGIN { printf "%d", int(t * 2 + 1e-9) + 1 }')
written=$(find "$out/overview/frames" -name '*.png' | wc -l)
[[ $written -eq $expected ]] || { echo "$written frames, expected $expected (end $end s)"; exit 1; }
grep -Eq "^frames +$expected at 2 fps" "$out/replay.log" || { echo "frames line disagrees"; exit 1; }
last=$(printf '%06d.png' $((expected - 1)))
for frame in 000000.png "$last"; do
  size=$(od -An -tu1 -j16 -N8 "$out/overview/frames/$frame" | awk '{ print $3*256+$4 "x" $7*256+$8 }')
  [[ $size == 160x120 ]] || { echo "$frame is $size"; exit 1; }
done
# The first and the last frame differ (the units moved, the clock ran).
! cmp -s "$out/overview/frames/000000.png" "$out/overview/frames/$last" ||
  { echo "first and last frames are identical"; exit 1; }

"$coinspect" replay "$out/run/run.rawlog" --fps 1 --size 160x120 --view chase:inspector1 \
  --out "$out/chase" > /dev/null 2>&1
test -s "$out/chase/frames/000000.png" || { echo "no chase frame"; exit 1; }

set +e
"$coinspect" replay "$out/run/run.rawlog" --view chase:nobody --out "$out/none" \
  > /dev/null 2> "$out/none.err"
status=$?
set -e
cat "$out/none.err"
[[ $status -eq 2 ]] || { echo "unknown unit: exit status $status, expected 2"; exit 1; }
grep -q 'inspector1' "$out/none.err" || { echo "the known units are not listed"; exit 1; }
echo "replay end-to-end: ok"
