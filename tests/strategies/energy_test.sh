#!/bin/bash
# End to end: explorers on a battery (slei-b-energy.ini). slei3d must keep them alive by
# charging at the station (each explorer charges from below 60 % to full at least once); a
# strategy that does not manage batteries must lose an explorer to an empty one, or the limit
# does not bind and the test shows nothing: the demo flight (demo-paths, <demo config>: its
# explorers orbit the building and never come near the station). caric-team, which does not
# manage them either, was the unmanaged one until its explorers came to charge by chance while
# handing out at the station.
# Usage: energy_test.sh <coinspect> <config> <scratch dir> <demo config>
set -euo pipefail
out=$3
rm -rf "$out" "$out-unmanaged"
"$1" run "$2" --quiet --out "$out" > "$out.log"
grep -E '^(features|collisions) |battery' "$out.log"
grep -qE '^collisions +0 \(deaths 0\)' "$out.log" || { echo "slei3d lost a unit"; exit 1; }
for explorer in explorer1 explorer2; do
  charged=$(awk -F, -v u="$explorer" '{ gsub(/"/, "", $4); level = $4 + 0 }
    $3 == u && $2 == "charge-start" { from = level }
    $3 == u && $2 == "charge-end" && level == 100 && from < 60 { n++ } END { print n + 0 }' \
    "$out/events.csv")
  echo "$explorer: full charges from below 60 %: $charged"
  [[ "$charged" -ge 1 ]] || { echo "$explorer never charged from low to full"; exit 1; }
done
# value SECTION KEY: the key's value in the config's section.
value() { awk -F' *= *' -v s="[$1]" -v k="$2" '/^\[/ { in_s = ($0 == s) } in_s && $1 == k { print $2 }' "$config"; }
config=$2
"$1" run "$4" --set mission.objective=features --set "mission.budget=$(value mission budget)" \
  --set "energy.capacity=$(value energy capacity)" \
  --set "energy.charge_time=$(value energy charge_time)" \
  --quiet --out "$out-unmanaged" > "$out-unmanaged.log"
grep -qE ',death,explorer[12],"battery empty"' "$out-unmanaged/events.csv" ||
  { echo "demo-paths kept its explorers alive: the battery limit does not bind"; exit 1; }
echo "ok"
