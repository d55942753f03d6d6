#!/bin/bash
# End-to-end: `coinspect plot-timeline`. PART picture: a short SLEI3D feature mission records an
# activity for every unit; its run folder (and its run.rawlog given directly) makes one PNG of the
# requested size, the same bytes twice; a truncated copy of the rawlog still draws, with exit 1,
# and one cut before any activity event reports the damage (exit 1).
# PART errors (no mission flown): a missing run, a folder without run.rawlog, a file that is not
# a rawlog, a CARIC run (no activity events) and bad sizes exit 2 naming the file or the option
# and write no picture.
# Usage: plot_timeline_test.sh <coinspect> <source dir> <scratch dir> picture|errors
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
part=$4
source "$(dirname "$0")/../check_png.sh"
picture_command=plot-timeline
source "$(dirname "$0")/expect_bad.sh"
rm -rf "$out"
mkdir -p "$out"

case $part in
  picture)
    "$coinspect" run "$source_dir/tests/strategies/slei-b-short.ini" --set mission.budget=20 \
      --quiet --out "$out/run" > "$out/run.log"
    # Every unit (one TUM trajectory each) has its activity recorded from the start.
    units=$(ls "$out/run"/*.tum | wc -l)
    reporting=$(grep ',activity-changed,' "$out/run/events.csv" | cut -d, -f3 | sort -u | wc -l)
    echo "units $units, units with activity events $reporting"
    [[ $units -gt 1 && $reporting -eq $units ]] || { echo "not every unit's activity"; exit 1; }
    "$coinspect" plot-timeline --out "$out/pictures/timeline.png" --size 640x360 "$out/run" \
      > "$out/plot.log"
    cat "$out/plot.log"
    grep -qx "$out/pictures/timeline.png" "$out/plot.log" || { echo "path not printed"; exit 1; }
    check_png "$out/pictures/timeline.png" 640 360
    # The rawlog itself: the same picture, byte for byte.
    "$coinspect" plot-timeline --out "$out/again.png" --size 640x360 "$out/run/run.rawlog" \
      > /dev/null
    cmp "$out/pictures/timeline.png" "$out/again.png" || { echo "not deterministic"; exit 1; }
    "$coinspect" plot-timeline --out "$out/default.png" "$out/run" > /dev/null
    check_png "$out/default.png" 1200 800
    # Damaged: drawn up to the damage, exit status 1.
    mkdir -p "$out/cut"
    size=$(stat -c %s "$out/run/run.rawlog")
    head -c $((size * 2 / 3)) "$out/run/run.rawlog" > "$out/cut/run.rawlog"
    set +e
    "$coinspect" plot-timeline --out "$out/cut.png" --size 320x200 "$out/cut" > /dev/null \
      2> "$out/cut.err"
    status=$?
    set -e
    cat "$out/cut.err"
    [[ $status -eq 1 ]] || { echo "damaged rawlog: exit status $status, expected 1"; exit 1; }
    grep -q "rawlog damaged" "$out/cut.err" || { echo "damage not reported"; exit 1; }
    check_png "$out/cut.png" 320 200
    # Cut before its first activity event: the damage is reported (it once read as "not the
    # rawlog of a feature mission", exit 2), exit 1, no picture.
    head -c 10000 "$out/run/run.rawlog" > "$out/early.rawlog"
    set +e
    "$coinspect" plot-timeline --out "$out/early.png" "$out/early.rawlog" > /dev/null \
      2> "$out/early.err"
    status=$?
    set -e
    cat "$out/early.err"
    [[ $status -eq 1 ]] || { echo "early cut: exit status $status, expected 1"; exit 1; }
    grep -q "rawlog damaged, no timeline before the damage: .*early.rawlog: [0-9]* objects read, damage at byte offset" \
      "$out/early.err" || { echo "early damage not reported"; exit 1; }
    [[ ! -e $out/early.png ]] || { echo "a picture of nothing was written"; exit 1; }
    ;;
  errors)
    caric_run="$source_dir/datasets/runs/hangar-strict"
    mkdir -p "$out/empty"
    echo 'not a rawlog' > "$out/notes.txt"
    expect_bad "^coinspect: error: $out/nowhere: no such run folder" "$out/nowhere"
    expect_bad "$out/empty/run.rawlog: no run.rawlog in the run folder" "$out/empty"
    expect_bad "$out/notes.txt" "$out/notes.txt"
    expect_bad "$caric_run/run.rawlog: no activity-changed event: not the rawlog of a feature" \
      "$caric_run"
    expect_bad "--size: '12xlarge' is not WIDTHxHEIGHT" --size 12xlarge "$caric_run"
    expect_bad "--size: '10x10': width and height must be 64 to 8192" --size 10x10 "$caric_run"
    ;;
  *)
    echo "unknown part '$part'"
    exit 1
    ;;
esac
echo "plot-timeline end-to-end ($part): ok"
