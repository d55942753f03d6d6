#!/usr/bin/env bash
# End-to-end test of `coinspect demo`: it runs, covers most points of a small generated scenario,
# writes a PNG, is deterministic, and rejects bad options with exit code 2.
set -euo pipefail
coinspect="$1"
work="$2"
rm -rf "$work" && mkdir -p "$work"

"$coinspect" demo --scenario slei-b --seed 4 --out "$work/a" --width 160 --height 96 >"$work/a.txt"
cat "$work/a.txt"
"$coinspect" demo --scenario slei-b --seed 4 --out "$work/b" --width 160 --height 96 >"$work/b.txt"

# Same scenario and seed: same summary (timing lines aside) and the same picture.
diff <(grep -v -e '^timing' -e '^picture' "$work/a.txt") \
     <(grep -v -e '^timing' -e '^picture' "$work/b.txt")
cmp "$work/a/demo.png" "$work/b/demo.png"
[[ "$(head -c 4 "$work/a/demo.png" | od -An -c | tr -d ' ')" == '211PNG' ]]

# With a viewpoint in front of every point, almost every point must be detected.
read -r detected total < <(sed -n 's/^gcs tally  detected \([0-9]*\) \/ \([0-9]*\).*/\1 \2/p' "$work/a.txt")
(( total == 150 )) || { echo "expected 150 points, got $total"; exit 1; }
(( detected * 10 >= total * 9 )) || { echo "only $detected of $total detected"; exit 1; }

# A bad scoring mode and an unknown scenario are input errors (exit 2) naming what is wrong.
set +e
"$coinspect" demo --scenario slei-b --mode fuzzy --out "$work/c" 2>"$work/err1.txt"; status1=$?
"$coinspect" demo --scenario no-such-place --out "$work/c" 2>"$work/err2.txt"; status2=$?
set -e
(( status1 == 2 )) && grep -q "fuzzy" "$work/err1.txt"
(( status2 == 2 )) && grep -q "no-such-place" "$work/err2.txt"
echo "demo end-to-end: ok"
