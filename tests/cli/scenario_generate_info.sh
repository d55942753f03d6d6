#!/usr/bin/env bash
# `scenario generate` writes a folder that `scenario info` reads back as the same scenario: the
# content hash printed for the folder equals the one of the generator itself.
#   scenario_generate_info.sh COINSPECT OUT_DIR
set -euo pipefail
coinspect=$1
out=$2
rm -rf "$out"
"$coinspect" scenario generate mbs --seed 3 --out "$out"
[[ -s "$out/scenario.ini" ]] || { echo "FAIL: no scenario.ini in $out" >&2; exit 1; }
from_folder=$("$coinspect" scenario info "$out/scenario.ini")
from_generator=$("$coinspect" scenario info mbs --seed 3)
echo "$from_folder"
grep -Eq '^name: mbs$' <<<"$from_folder" || { echo "FAIL: name" >&2; exit 1; }
grep -Eq '^boxes: [4-9]' <<<"$from_folder" || { echo "FAIL: boxes" >&2; exit 1; }
grep -Eq '^interest points: [0-9]+, median nearest-neighbour spacing 0\.[6-9]' <<<"$from_folder" ||
  { echo "FAIL: interest point line" >&2; exit 1; }
grep -Eq '^  jurong +explorer' <<<"$from_folder" || { echo "FAIL: fleet" >&2; exit 1; }
grep -Eq '^budget: 600 s$' <<<"$from_folder" || { echo "FAIL: budget" >&2; exit 1; }
hash_folder=$(sed -n 's/^content hash: //p' <<<"$from_folder")
hash_generator=$(sed -n 's/^content hash: //p' <<<"$from_generator")
[[ -n "$hash_folder" && "$hash_folder" == "$hash_generator" ]] ||
  { echo "FAIL: hash $hash_folder (folder) != $hash_generator (generator)" >&2; exit 1; }
# Read from inside its folder by a bare file name, whose folder is then empty: that once failed
# with "filesystem error: cannot make absolute path".
hash_inside=$(cd "$out" && "$coinspect" scenario info scenario.ini | sed -n 's/^content hash: //p')
[[ "$hash_inside" == "$hash_generator" ]] ||
  { echo "FAIL: hash $hash_inside (from inside the folder) != $hash_generator" >&2; exit 1; }
# A different seed is a different scenario.
hash_other=$("$coinspect" scenario info mbs --seed 4 | sed -n 's/^content hash: //p')
[[ "$hash_other" != "$hash_generator" ]] || { echo "FAIL: seed 4 has the seed 3 hash" >&2; exit 1; }
