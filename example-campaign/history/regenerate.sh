#!/usr/bin/env bash
# Regenerates the example plant's inspection history: four earlier yearly inspections
# (2022–2025) simulated from the same models with other seeds, in which VMC-07 Y's nut wears
# (its reversal grows by 1.2 µm a year to today's 6.5 µm), and today's inspection (the
# campaign's own data, 2026-11-20). The reference and real files are the same every year.
# Usage: bash example-campaign/history/regenerate.sh   (AXCHECK=path/to/axcheck to skip cargo)
set -euo pipefail
cd "$(dirname "$0")/.."
axcheck() {
  if [ -n "${AXCHECK:-}" ]; then "$AXCHECK" "$@"; else cargo run --release --quiet -- "$@"; fi
}
rm -rf history/year=*
for year in 2022 2023 2024 2025; do
  tmp=$(mktemp -d)
  cp -r campaign.yaml specs data "$tmp/"
  wear=$(( 2026 - year ))
  for model in models/*.yaml; do
    name=$(basename "$model" .yaml)
    # Another seed each year; the worn nut's reversal 1.2 µm less per year before today.
    sed -e "s/^seed: \([0-9]*\)/seed: \1$year/" "$model" > "$tmp/$name.yaml"
    if [ "$name" = vmc07-y ]; then
      sed -i -e "s/^  reversal_um: .*/  reversal_um: $(awk "BEGIN {print 6.5 - 1.2 * $wear}")/" \
             -e "s/^  reversal_end_um: .*/  reversal_end_um: $(awk "BEGIN {print 8.0 - 1.2 * $wear}")/" "$tmp/$name.yaml"
    fi
    axcheck simulate "$tmp/$name.yaml" -o "$tmp/data/$name.csv" > /dev/null 2>&1
  done
  sed -i "s/^  date: .*/  date: $year-11-20/" "$tmp/campaign.yaml"
  # The certified machines' lasers were calibrated every year: the calibration valid then.
  sed -i -e "s/calibrated_on: 2026-/calibrated_on: $year-/" -e "s/due: 2027-/due: $(( year + 1 ))-/" \
    "$tmp/campaign.yaml"
  axcheck run "$tmp/campaign.yaml" --out "$tmp/out" --no-pdf --history history > /dev/null 2>&1 || true
  rm -rf "$tmp"
done
axcheck run campaign.yaml --out "$(mktemp -d)" --no-pdf --history history > /dev/null 2>&1 || true
