#!/bin/bash
# End to end: explore-then-inspect hands nothing out before every box is explored, so on the
# whole of slei-b its first hand-out comes at about 340 s. To keep the test short it flies slei-b
# cut to its two southern boxes (scenario generated here, the northern [box.*] sections dropped),
# then makes the checks of feature_mission_test.sh.
# Usage: explore_then_inspect_test.sh <coinspect> <config> <min discovered> <min assigned>
#        <min collected> <scratch dir>
set -euo pipefail
coinspect=$1
config=$2
out=$6
scenario=$out-scenario
rm -rf "$scenario"
"$coinspect" scenario generate slei-b --seed 1 --out "$scenario" > /dev/null
awk '/^\[box\.north/ { skip = 1; next } /^\[/ { skip = 0 } !skip' "$scenario/scenario.ini" \
  > "$scenario/south.ini"
test "$(grep -c '^\[box\.' "$scenario/south.ini")" = 2 || { echo "slei-b has no two southern boxes"; exit 1; }
exec bash "$(dirname "$0")/feature_mission_test.sh" "$coinspect" "$config" explore-then-inspect \
  "$3" "$4" "$5" "$out" --set "mission.scenario=$scenario/south.ini"
