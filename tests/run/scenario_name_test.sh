#!/bin/bash
# End-to-end: a run's output folder named after its scenario (`--out slei-b`, beside the INI and in
# the working folder) does not hide the generator: the same mission runs again from there, and its
# recording is evaluated from there (doc/config.md, "Command-line options").
# Usage: scenario_name_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cp "$source_dir/config/quick.ini" "$work/mission.ini"
grep -q '^scenario = slei-b$' "$work/mission.ini" || { echo "quick.ini no longer flies slei-b"; exit 1; }
cd "$work"
"$coinspect" run mission.ini --set mission.budget=5 --quiet --out slei-b > first.log
test -d slei-b && test -s slei-b/run.rawlog
"$coinspect" run mission.ini --set mission.budget=5 --quiet --out again > second.log
cmp slei-b/run.rawlog again/run.rawlog
"$coinspect" eval slei-b/run.rawlog > eval.log
"$coinspect" scenario info slei-b | grep -q '^name: slei-b'
# The folder itself, named as a path, is not a scenario: a clear error, exit code 2.
set +e
"$coinspect" scenario info ./slei-b 2> info.err
status=$?
set -e
cat info.err
(( status == 2 )) && grep -q 'holds neither box_description.yaml (CARIC) nor scenario.ini' info.err
