#!/bin/bash
# End-to-end: `coinspect plot-features` on hand-made feature-mission reports. PART pictures: two
# runs (a run folder and a report.json path, with and without a label) make one PNG of the
# requested size, the same bytes twice, another picture for another --stage (also priority). PART missing,
# values, options: bad input exits 2 naming the file and the key (or the option) and writes no
# picture. The parts are separate tests because each coinspect start costs a few tenths of a
# second.
# Usage: plot_features_test.sh <coinspect> <scratch dir> pictures|missing|values|options
set -euo pipefail
coinspect=$1
out=$2
part=$3
source "$(dirname "$0")/../check_png.sh"
picture_command=plot-features
source "$(dirname "$0")/expect_bad.sh"
rm -rf "$out"
mkdir -p "$out/seed1" "$out/seed2"

# feature_report FILE STRATEGY TOTAL BUDGET COLLECTED INSPECTED: a report.json as coinspect run
# writes it for a feature mission, reduced to what plot-features reads (and a little more).
feature_report() {
  cat > "$1" <<EOF
{
  "clock": {"budget": $4, "mission_time": $4, "started": true},
  "config": {"file": "slei.ini", "values": {"strategy": {"name": "$2"}}},
  "scenario": "slei-a",
  "strategy": "$2",
  "features": {
    "total": $3,
    "collected": 3,
    "priority": {"total": 2, "collected": 1, "finish_time": null},
    "timeline": {
      "discovered": [1.5, 2.0, 4.0, 9.0],
      "assigned": [3.0, 5.0, 9.5],
      "inspected": $6,
      "collected": $5,
      "priority": [12.5]
    }
  }
}
EOF
}
feature_report "$out/seed1/report.json" slei3d 6 120 '[40.0, 12.5, 12.5]' '[10.0, 11.0, 30.0]'
feature_report "$out/seed2/report.json" slei3d 6 100 '[70.25]' '[]'

case $part in
  pictures)
    # A run folder and a report.json of the same strategy (labels add the folder), 320x240.
    "$coinspect" plot-features --out "$out/pictures/collected.png" --size 320x240 \
      "$out/seed1" "$out/seed2/report.json" > "$out/plot.log"
    cat "$out/plot.log"
    grep -qx "$out/pictures/collected.png" "$out/plot.log" || { echo "path not printed"; exit 1; }
    check_png "$out/pictures/collected.png" 320 240
    # Same input, same bytes.
    "$coinspect" plot-features --out "$out/again.png" --size 320x240 "$out/seed1" \
      "$out/seed2/report.json" > /dev/null
    cmp "$out/pictures/collected.png" "$out/again.png" || { echo "not deterministic"; exit 1; }
    # A label given, another stage: other curves; the default size.
    "$coinspect" plot-features --out "$out/inspected.png" --stage inspected \
      "$out/seed1=first seed" "$out/seed2" > /dev/null
    check_png "$out/inspected.png" 1200 800
    "$coinspect" plot-features --out "$out/collected.png" "$out/seed1=first seed" "$out/seed2" \
      > /dev/null
    if cmp -s "$out/collected.png" "$out/inspected.png"; then
      echo "--stage inspected drew the collected picture"; exit 1
    fi
    # The high-priority features collected, counted up to their own total (2).
    "$coinspect" plot-features --out "$out/priority.png" --stage priority "$out/seed1=first seed" \
      "$out/seed2" > /dev/null
    check_png "$out/priority.png" 1200 800
    if cmp -s "$out/collected.png" "$out/priority.png"; then
      echo "--stage priority drew the collected picture"; exit 1
    fi
    ;;
  missing)
    echo 'this is not json' > "$out/notes.txt"
    mkdir -p "$out/empty" "$out/caric" "$out/garbled"
    echo '{"clock": {"budget": 600}, "scenario": "hangar", "strategy": "kios", "score": 1.5}' \
      > "$out/caric/report.json"
    echo '{"features": {"timeline": [1, 2' > "$out/garbled/report.json"
    expect_bad "^coinspect: error: $out/nowhere: no such run folder" "$out/seed1" "$out/nowhere"
    expect_bad "$out/empty/report.json: no report.json" "$out/empty"
    expect_bad "$out/notes.txt: not JSON" "$out/notes.txt"
    expect_bad "$out/garbled/report.json: not JSON" "$out/garbled"
    expect_bad "$out/caric/report.json: features.timeline: missing: not the report of a feature" \
      "$out/caric"
    ;;
  values)
    mkdir -p "$out/negative" "$out/nan" "$out/no-total" "$out/no-budget"
    feature_report "$out/negative/report.json" slei3d 6 120 '[4.0, -3.0]' '[]'
    feature_report "$out/nan/report.json" slei3d 6 120 '[null]' '[]'
    sed 's/"total": 6,//' "$out/seed1/report.json" > "$out/no-total/report.json"
    sed 's/"budget": 120,//' "$out/seed1/report.json" > "$out/no-budget/report.json"
    expect_bad "$out/negative/report.json: features.timeline.collected\[1\]: -3.0 is not a time" \
      "$out/negative"
    # A NaN is written as null by the JSON writer.
    expect_bad "$out/nan/report.json: features.timeline.collected\[0\]: null is not a time" \
      "$out/nan"
    expect_bad "$out/no-total/report.json: features.total: missing" "$out/no-total"
    sed 's/"priority": {"total": 2,/"priority": {/' "$out/seed1/report.json" \
      > "$out/no-total/report.json"
    expect_bad "$out/no-total/report.json: features.priority.total: missing" --stage priority \
      "$out/no-total"
    expect_bad "$out/no-budget/report.json: clock.budget: missing" "$out/no-budget"
    ;;
  options)
    expect_bad "--stage: 'explored' is not a stage" --stage explored "$out/seed1"
    expect_bad "--size: '12xlarge' is not WIDTHxHEIGHT" --size 12xlarge "$out/seed1"
    expect_bad "$out/seed1=: empty LABEL" "$out/seed1="
    ;;
  *)
    echo "unknown part '$part'"
    exit 1
    ;;
esac
echo "plot-features end-to-end ($part): ok"
