#!/usr/bin/env bash
# Runs one command and checks its exit code and that its output (stdout + stderr, lines joined
# by spaces so that a pattern may span lines) matches an extended regular expression.
#   expect.sh EXIT_CODE REGEX COMMAND [ARGS...]
set -euo pipefail
expected_rc=$1
regex=$2
shift 2
set +e
output=$("$@" 2>&1)
rc=$?
set -e
printf '%s\n--- exit code %d\n' "$output" "$rc"
if [[ $rc -ne $expected_rc ]]; then
  echo "FAIL: expected exit code $expected_rc, got $rc" >&2
  exit 1
fi
if ! tr '\n' ' ' <<<"$output" | grep -Eq -- "$regex"; then
  echo "FAIL: output does not match: $regex" >&2
  exit 1
fi
