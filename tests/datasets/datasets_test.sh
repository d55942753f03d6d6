#!/usr/bin/env bash
# The scenarios stored in datasets/ load, and equal what the generators make today.
set -euo pipefail
coinspect="$1"
datasets="$2"
for folder in "$datasets"/*/; do
  [[ -f "$folder/scenario.ini" ]] || continue  # runs/ holds recorded missions, not a scenario
  name=$(basename "$folder")
  stored=$("$coinspect" scenario info "$folder" | sed -n 's/^content hash: //p')
  generated=$("$coinspect" scenario info "$name" --seed 1 | sed -n 's/^content hash: //p')
  [[ -n "$stored" && "$stored" == "$generated" ]] ||
    { echo "datasets/$name: stored hash '$stored' != generated '$generated'"; exit 1; }
  echo "datasets/$name: $stored"
done
