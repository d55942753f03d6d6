#!/usr/bin/env bash
# `scenario export` writes STL, PLY, PCD and CSV files whose sizes and counts agree with
# `scenario info`; unknown extensions are input errors (exit code 2).
#   scenario_export.sh COINSPECT OUT_DIR
set -euo pipefail
coinspect=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $*" >&2; exit 1; }

info=$("$coinspect" scenario info hangar)
triangles=$(sed -n 's/^triangles: \([0-9]*\) .*/\1/p' <<<"$info")
points=$(sed -n 's/^interest points: \([0-9]*\),.*/\1/p' <<<"$info")
[[ $triangles -gt 0 && $points -gt 0 ]] || fail "info: $triangles triangles, $points points"

"$coinspect" scenario export hangar --mesh "$out/hangar.stl" --points "$out/hangar.pcd"
"$coinspect" scenario export hangar --mesh "$out/hangar.ply" --points "$out/hangar.csv"
for f in hangar.stl hangar.ply hangar.pcd hangar.csv; do
  [[ -s "$out/$f" ]] || fail "$f missing or empty"
done
# Binary STL: 80-byte header, 4-byte count, 50 bytes per triangle.
stl_size=$(stat -c %s "$out/hangar.stl")
[[ $stl_size -eq $((84 + 50 * triangles)) ]] || fail "STL is $stl_size bytes for $triangles triangles"
head -c 3 "$out/hangar.ply" | grep -q '^ply' || fail "PLY magic"
grep -aq "^element face $triangles\$" "$out/hangar.ply" || fail "PLY face count"
grep -aq "^POINTS $points\$" "$out/hangar.pcd" || fail "PCD point count"
grep -aq '^FIELDS normal_x normal_y normal_z x y z _' "$out/hangar.pcd" || fail "PCD fields"
[[ $(head -n 1 "$out/hangar.csv") == "x,y,z,nx,ny,nz,idx" ]] || fail "CSV header"
[[ $(($(wc -l <"$out/hangar.csv") - 1)) -eq $points ]] || fail "CSV rows"

set +e
message=$("$coinspect" scenario export hangar --mesh "$out/hangar.obj" 2>&1)
rc=$?
set -e
[[ $rc -eq 2 && $message == *"hangar.obj"* && $message == *"coinspect: error:"* ]] ||
  fail "unknown mesh extension: rc $rc, $message"
set +e
message=$("$coinspect" scenario export hangar --points "$out/hangar.xyz" 2>&1)
rc=$?
set -e
[[ $rc -eq 2 && $message == *"hangar.xyz"* ]] || fail "unknown point extension: rc $rc, $message"
echo "ok"
