#!/usr/bin/env bash
# Regenerates every simulated measurement file of the example campaign from its model.
set -euo pipefail
cd "$(dirname "$0")"
for model in models/*.yaml; do
  name=$(basename "$model" .yaml)
  cargo run --release --quiet -- simulate "$model" -o "data/$name.csv"
done
