#!/bin/bash
# End-to-end: `coinspect run --out` records run.rawlog; `coinspect eval` scores it again, finds
# the recorded score (exit 0, "equal"), prints coverage at each tenth of the run and writes
# eval.json and coverage.csv. A truncated copy of the rawlog is evaluated up to the damage: exit 1,
# the message names the objects read and the byte offset; so is a copy with a damaged class name,
# whose message eval.json holds. A run of a scenario folder named relative to its INI evaluates
# from another folder. Usage: eval_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
source "$(dirname "$0")/../record_short_run.sh"
record_short_run "$coinspect" "$source_dir" "$out" 20

# The whole rawlog: equal, exit 0, files written.
set +e
"$coinspect" eval "$out/run/run.rawlog" --out "$out/eval" > "$out/eval.log" 2> "$out/eval.err"
status=$?
set -e
cat "$out/eval.log"
[[ $status -eq 0 ]] || { cat "$out/eval.err"; echo "eval exit status $status, expected 0"; exit 1; }
grep -Eq '^re-scored +Q = [0-9.]+, detected [0-9]+ / 150: equal$' "$out/eval.log" ||
  { echo "no 'equal' line"; exit 1; }
# The two printed scores agree (equal already compares them exactly) and are not 0.
recorded=$(sed -nE 's/^recorded +Q = ([0-9.]+),.*/\1/p' "$out/eval.log")
rescored=$(sed -nE 's/^re-scored +Q = ([0-9.]+),.*/\1/p' "$out/eval.log")
[[ -n $recorded && $recorded == "$rescored" ]] || { echo "recorded $recorded != $rescored"; exit 1; }
awk -v q="$recorded" 'BEGIN { exit !(q > 0) }' || { echo "Q is 0"; exit 1; }
grep -Eq '^inspector1 +photographer +[1-9][0-9]* ' "$out/eval.log" ||
  { echo "no unit row for inspector1"; exit 1; }
# The printed coverage: ten tenths, never falling, ending at the re-scored Q and detected count.
detected=$(sed -nE 's/^re-scored +Q = [0-9.]+, detected ([0-9]+) .*/\1/p' "$out/eval.log")
awk -v q="$rescored" -v d="$detected" '
  $1 == "Q" { n = NF - 1; for (i = 3; i <= NF; ++i) if ($i < $(i - 1)) bad = 1; lastQ = $NF }
  $1 == "detected" { m = NF - 1; for (i = 3; i <= NF; ++i) if ($i < $(i - 1)) bad = 1; lastD = $NF }
  END { exit !(n == 10 && m == 10 && !bad && lastQ == sprintf("%.3f", q) && lastD == d) }' \
  "$out/eval.log" || { echo "bad coverage rows"; exit 1; }
grep -q '"equal": true' "$out/eval/eval.json" || { echo "eval.json lacks equal: true"; exit 1; }
head -1 "$out/eval/coverage.csv" | grep -qx 'time,score,detected' || { echo "bad coverage.csv"; exit 1; }
[[ $(wc -l < "$out/eval/coverage.csv") -gt 1 ]] || { echo "coverage.csv has no sample"; exit 1; }

# A scenario folder given relative to its INI (as config/caric-mbs.ini does), recorded into a
# folder at another depth: eval finds it from the rawlog (it once resolved the INI's relative
# path from the rawlog's folder and found nothing).
"$coinspect" scenario generate slei-b --out "$out/scene/slei-b" > /dev/null
mkdir -p "$out/ini"
sed 's|^scenario = slei-b$|scenario = ../scene/slei-b|' "$source_dir/config/quick.ini" > "$out/ini/quick.ini"
grep -q '^scenario = ../scene/slei-b$' "$out/ini/quick.ini" || { echo "scenario not replaced"; exit 1; }
"$coinspect" run "$out/ini/quick.ini" --set mission.budget=3 --quiet --out "$out/a/b/folder-run" \
  > /dev/null
"$coinspect" eval "$out/a/b/folder-run/run.rawlog" > "$out/folder-eval.log" 2> /dev/null ||
  { cat "$out/folder-eval.log"; echo "eval of a folder-scenario run failed"; exit 1; }
grep -Eq '^re-scored +Q = [0-9.]+, detected [0-9]+ / 150: equal$' "$out/folder-eval.log" ||
  { echo "folder-scenario run: no 'equal' line"; exit 1; }

# A truncated copy: results up to the damage, exit 1, the reader's message on stderr.
size=$(stat -c %s "$out/run/run.rawlog")
head -c $((size / 2)) "$out/run/run.rawlog" > "$out/cut.rawlog"
set +e
"$coinspect" eval "$out/cut.rawlog" > "$out/cut.log" 2> "$out/cut.err"
status=$?
set -e
cat "$out/cut.log" "$out/cut.err"
[[ $status -eq 1 ]] || { echo "truncated rawlog: exit status $status, expected 1"; exit 1; }
grep -Eq 'rawlog damaged: .*cut\.rawlog: [0-9]+ objects read, damage at byte offset [0-9]+' \
  "$out/cut.err" || { echo "no damage message with objects and offset"; exit 1; }
grep -Eq '^read +[0-9]+ objects to t = [0-9.]+ s, then DAMAGED at byte offset [0-9]+' \
  "$out/cut.log" || { echo "no damaged read line"; exit 1; }
grep -Eq '^re-scored +Q = ' "$out/cut.log" || { echo "no results before the damage"; exit 1; }

# A damaged class name mid-file: the name's bytes reach the damage message, which must still be
# written into eval.json (a byte that is not UTF-8 once left the file empty), escaped as \xNN.
gzip -dc "$out/run/run.rawlog" > "$out/named.raw"
offset=$(grep -boa 'CObservationIMU' "$out/named.raw" | sed -n '50{s/:.*//;p}')
[[ -n $offset ]] || { echo "no 50th CObservationIMU in the rawlog"; exit 1; }
printf '\x90' | dd of="$out/named.raw" bs=1 seek="$offset" conv=notrunc status=none
gzip -c "$out/named.raw" > "$out/named.rawlog"
set +e
"$coinspect" eval "$out/named.rawlog" --out "$out/named" > "$out/named.log" 2> "$out/named.err"
status=$?
set -e
cat "$out/named.err"
[[ $status -eq 1 ]] || { echo "damaged class name: exit status $status, expected 1"; exit 1; }
grep -qF 'mrpt::obs::\\x90ObservationIMU' "$out/named/eval.json" ||
  { echo "eval.json lacks the escaped class name"; exit 1; }
grep -q '"clean": false' "$out/named/eval.json" || { echo "eval.json lacks clean: false"; exit 1; }
[[ $(tail -1 "$out/named/eval.json") == "}" ]] || { echo "eval.json is cut short"; exit 1; }
echo "eval end-to-end: ok"
