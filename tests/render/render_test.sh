#!/bin/bash
# End-to-end: `coinspect run --out` records a short mission; `coinspect render` draws it (every
# picture a PNG of the requested size, the scene file non-empty), also into another folder and
# from a truncated copy (exit 1, pictures still written); bad options exit 2.
# Usage: render_test.sh <coinspect> <source dir> <scratch dir>
set -euo pipefail
coinspect=$1
source_dir=$2
out=$3
source "$(dirname "$0")/../record_short_run.sh"
source "$(dirname "$0")/../check_png.sh"
record_short_run "$coinspect" "$source_dir" "$out" 6

# Default folder: the rawlog's; the paths are printed in order.
"$coinspect" render "$out/run/run.rawlog" --size 320x240 > "$out/render.log"
cat "$out/render.log"
for name in score.png top.png side.png final3d.png scene.3Dscene; do
  grep -qx "$out/run/$name" "$out/render.log" || { echo "$name not printed"; exit 1; }
  test -s "$out/run/$name" || { echo "$name missing or empty"; exit 1; }
done
for name in score top side final3d; do check_png "$out/run/$name.png" 320 240; done

# --out elsewhere (created), another size.
"$coinspect" render "$out/run/run.rawlog" --size 200x150 --out "$out/pictures" > /dev/null
for name in score top side final3d; do check_png "$out/pictures/$name.png" 200 150; done
test -s "$out/pictures/scene.3Dscene" || { echo "no scene.3Dscene in --out"; exit 1; }

# A truncated rawlog: pictures up to the damage, exit 1, the reader's message.
size=$(stat -c %s "$out/run/run.rawlog")
mkdir -p "$out/cut"
head -c $((size / 2)) "$out/run/run.rawlog" > "$out/cut/run.rawlog"
set +e
"$coinspect" render "$out/cut/run.rawlog" --size 160x120 > /dev/null 2> "$out/cut.err"
status=$?
set -e
cat "$out/cut.err"
[[ $status -eq 1 ]] || { echo "truncated rawlog: exit status $status, expected 1"; exit 1; }
grep -Eq 'damage at byte offset [0-9]+' "$out/cut.err" || { echo "no damage message"; exit 1; }
check_png "$out/cut/top.png" 160 120

# Bad input: exit 2 with the option named.
set +e
"$coinspect" render "$out/run/run.rawlog" --size 12xlarge > /dev/null 2> "$out/bad.err"
status=$?
set -e
[[ $status -eq 2 ]] && grep -q -- '--size' "$out/bad.err" || { echo "bad --size: status $status"; exit 1; }
echo "render end-to-end: ok"
