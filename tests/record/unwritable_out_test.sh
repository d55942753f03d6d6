#!/usr/bin/env bash
# unwritable_out_test.sh <coinspect> <source dir> <scratch dir>
# `coinspect run --out` into a folder that cannot be created, or whose run.rawlog cannot be
# written, fails before the mission flies with exit status 2 and an error naming the path.
# (Permissions do not stop root, so the paths are made impossible instead.)
set -uo pipefail
coinspect=$1 source_dir=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; cat "$work/stderr.txt"; exit 1; }
run() {
  "$coinspect" run "$source_dir/config/quick.ini" --set mission.budget=1 --out "$1" \
    > "$work/stdout.txt" 2> "$work/stderr.txt"
}
touch "$work/a-file"
run "$work/a-file/out"
code=$?
[[ $code -eq 2 ]] || fail "folder under a file: exit status $code, expected 2"
grep -q "coinspect: error: $work/a-file/out: --out: cannot create the folder" "$work/stderr.txt" ||
  fail "the error does not name the folder"
mkdir -p "$work/out/run.rawlog"  # a folder where the rawlog should go
run "$work/out"
code=$?
[[ $code -eq 2 ]] || fail "rawlog path is a folder: exit status $code, expected 2"
grep -q "coinspect: error: $work/out/run.rawlog" "$work/stderr.txt" || fail "the error does not name run.rawlog"
grep -q "^score" "$work/stdout.txt" && fail "the mission flew although its rawlog could not be opened"
echo "unwritable --out paths are reported before the mission"
