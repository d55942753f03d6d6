#!/usr/bin/env bash
# `scenario bound --csv` writes one row per interest point with its best score per clearance; the
# totals it prints equal the sums of those columns, and no point scores more with more clearance.
#   scenario_bound_csv.sh COINSPECT OUT_DIR
set -euo pipefail
coinspect=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $*" >&2; exit 1; }

printed=$("$coinspect" scenario bound hangar --clearance 0,2 --csv "$out/bound.csv")
echo "$printed"
[[ $(head -n 1 "$out/bound.csv") == "idx,x,y,z,best_0,best_2" ]] || fail "CSV header"
[[ $(($(wc -l <"$out/bound.csv") - 1)) -eq 930 ]] || fail "CSV rows"
sums=$(awk -F, 'NR > 1 { a += $5; b += $6; if ($6 > $5 + 1e-9) bad++ }
                END { printf "%.2f %.2f %d", a, b, bad }' "$out/bound.csv")
read -r sum0 sum2 worse <<<"$sums"
[[ $worse -eq 0 ]] || fail "$worse points score more with 2 m of clearance than with none"
grep -Eq "^0\.00 +[0-9]+ +[0-9]+ +$sum0 " <<<"$printed" || fail "clearance 0 total is not $sum0"
grep -Eq "^2\.00 +[0-9]+ +[0-9]+ +$sum2 " <<<"$printed" || fail "clearance 2 total is not $sum2"
echo "OK: CSV sums $sum0 and $sum2 match the printed totals"
