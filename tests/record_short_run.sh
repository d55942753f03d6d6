# Sourced by the end-to-end tests of recorded runs (eval, render, replay).
# record_short_run COINSPECT SOURCE_DIR OUT BUDGET: empties OUT and records config/quick.ini with
# the given budget (s) into OUT/run (run.rawlog and the side outputs; its output in OUT/run.log).
record_short_run() {
  local coinspect=$1 source_dir=$2 out=$3 budget=$4
  rm -rf "$out"
  mkdir -p "$out"
  "$coinspect" run "$source_dir/config/quick.ini" --set mission.budget="$budget" --out "$out/run" \
    >"$out/run.log"
  test -s "$out/run/run.rawlog" || { echo "coinspect run wrote no run.rawlog"; exit 1; }
}
