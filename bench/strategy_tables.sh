#!/usr/bin/env bash
# The strategy tables of doc/strategies.md: every strategy on every scenario for several seeds,
# then one markdown row per (scenario, strategy) with the median and max score, the median
# detected points, collisions over all runs, the median real-time factor and the median p95
# decision time.
#
# usage: bench/strategy_tables.sh BUILD_DIR OUT_DIR [SEEDS] [SCENARIOS] [STRATEGIES] [JOBS]
#        bench/strategy_tables.sh --print OUT_DIR [SEEDS] [SCENARIOS] [STRATEGIES]
#   --print     only the rows of the runs already in OUT_DIR: nothing is run or written
#   SEEDS       "1 2 3 4 5"
#   SCENARIOS   "caric-mbs mbs crane hangar" (caric-mbs reads ../shared/data/caric-mbs)
#   STRATEGIES  "caric-baseline kios star coinspect"
#   JOBS        2 missions at a time
# The explorers fly `vlp16-tilting-noisy` (3 cm range noise) so that seeds give different runs;
# the reference's LiDAR is noiseless. Runs already in OUT_DIR (summary.txt present) are kept.
set -euo pipefail

print_only=false
if [[ ${1:-} == --print ]]; then
  print_only=true
  set -- - "${@:2}"
fi
build=${1:?usage: strategy_tables.sh BUILD_DIR OUT_DIR [SEEDS] [SCENARIOS] [STRATEGIES] [JOBS]}
out=${2:?usage: strategy_tables.sh BUILD_DIR OUT_DIR [SEEDS] [SCENARIOS] [STRATEGIES] [JOBS]}
seeds=${3:-1 2 3 4 5}
scenarios=${4:-caric-mbs mbs crane hangar}
strategies=${5:-caric-baseline kios star coinspect}
jobs=${6:-2}
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
coinspect="$build/bin/coinspect"
# Configs and runs in separate folders: a folder named like a generated scenario beside a
# config would be read as that scenario's files.
$print_only || mkdir -p "$out/configs" "$out/runs"

budget_of() {
  case $1 in
    hangar) echo 420 ;;
    *) echo 600 ;;
  esac
}

source_of() {
  if [[ $1 == caric-mbs ]]; then
    local data="$repo/../shared/data/caric-mbs"
    [[ -d $data ]] || { echo "strategy_tables: $data not found" >&2; exit 1; }
    (cd "$data" && pwd)
  else
    echo "$1"
  fi
}

# One mission config per scenario (written into OUT_DIR; the strategy comes from --set).
$print_only && scenarios_to_run="" || scenarios_to_run=$scenarios
for scenario in $scenarios_to_run; do
  cat >"$out/configs/$scenario.ini" <<EOF
[mission]
scenario = $(source_of "$scenario")
budget = $(budget_of "$scenario")
explorer_lidar = vlp16-tilting-noisy

[strategy]
name = caric-baseline
EOF
done

run_one() {
  local scenario=$1 strategy=$2 seed=$3
  local dir="$out/runs/$scenario/$strategy/seed$seed"
  [[ -f $dir/summary.txt ]] && return 0
  mkdir -p "$dir"
  "$coinspect" run "$out/configs/$scenario.ini" --set "strategy.name=$strategy" --seed "$seed" \
    --out "$dir" --quiet >"$dir/stdout.txt" 2>"$dir/stderr.txt" ||
    echo "strategy_tables: $scenario $strategy seed $seed failed (see $dir/stderr.txt)" >&2
}

for scenario in $scenarios_to_run; do
  for strategy in $strategies; do
    for seed in $seeds; do
      while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
      run_one "$scenario" "$strategy" "$seed" &
    done
  done
done
wait

median() { sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) print "-"; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
maximum() { sort -g | tail -1; }

echo "| scenario | strategy | runs | median Q | max Q | median detected | collisions | median rtf | median p95 decision |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for scenario in $scenarios; do
  for strategy in $strategies; do
    summaries=$(ls "$out/runs/$scenario/$strategy"/seed*/summary.txt 2>/dev/null || true)
    [[ -n $summaries ]] || continue
    runs=$(echo "$summaries" | wc -l)
    field() { for f in $summaries; do awk "$1" "$f"; done; }
    score=$(field '/^score/ { print $4 }')
    detected=$(field '/^detected/ { print $2 }')
    total=$(awk '/^detected/ { print $4; exit }' $(echo "$summaries" | head -1))
    collisions=$(field '/^collisions/ { print $2 }' | awk '{ s += $1 } END { print s }')
    rtf=$(field '/^real-time factor/ { sub(/x$/, "", $3); print $3 }')
    p95=$(field '/^decisions/ { for (i = 1; i <= NF; ++i) if ($i == "p95") print $(i + 1) }')
    printf '| %s | %s | %d | %s | %s | %s / %s | %s | %sx | %s ms |\n' "$scenario" "$strategy" \
      "$runs" "$(echo "$score" | median)" "$(echo "$score" | maximum)" \
      "$(echo "$detected" | median)" "$total" "$collisions" "$(echo "$rtf" | median)" \
      "$(echo "$p95" | median)"
  done
done
