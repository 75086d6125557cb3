#!/usr/bin/env bash
# Regenerates every simulated measurement file of the example campaign from its model, the
# compensation tables active on VMC-07 during the inspection, and MILL-3's compensation:
# measured, a table written, measured again with it loaded.
set -euo pipefail
cd "$(dirname "$0")"
axcheck() { cargo run --release --quiet -- "$@"; }
for model in models/*.yaml; do
  name=$(basename "$model" .yaml)
  case "$name" in mill3-*) continue ;; esac
  axcheck simulate "$model" -o "data/$name.csv"
done

# MILL-8 measured whole: beside each positioning test (above), X's straightness along Y
# and Z and its pitch and yaw, and Y's straightness along X (for the X–Y squareness).
for letter in Y Z B C; do
  lower=$(echo "$letter" | tr 'YZBC' 'yzbc')
  kind=e${lower}x
  axcheck simulate models/mill8-x.yaml --geometry "$letter" -o "data/mill8-x-$kind.csv"
done
axcheck simulate models/mill8-y.yaml --geometry X -o data/mill8-y-exy.csv

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# VMC-07's LEC tables, written at its 2025 acceptance with the compensation off, every
# 50 mm, zero at the reference point 0 mm; active during this inspection.
for axis in X Y Z; do
  lower=$(echo "$axis" | tr 'XYZ' 'xyz')
  axcheck simulate "models/active/vmc07-$lower-2025.yaml" -o "$scratch/$lower.csv"
  axcheck compensate "$scratch/$lower.csv" --controller siemens-840d --interval 50 \
    --reference 0 --axis "${axis}1" --active none -o "active/VMC-07/$axis.ini" >/dev/null
done

# MILL-3: measured with nothing active, its LinuxCNC tables written (type 1, trims, as its
# INI says) and loaded, measured again. X's table was loaded as written; Y's with every
# trim negated (the sign of LinuxCNC's INI documentation, not of its code).
for axis in X Y; do
  lower=$(echo "$axis" | tr 'XY' 'xy')
  model="models/mill3-$lower.yaml"
  axcheck simulate "$model" -o "data/mill3-$lower-before.csv"
  axcheck compensate "data/mill3-$lower-before.csv" --controller linuxcnc --active none \
    --comp-file-type 1 -o "active/MILL-3/$axis.txt" >/dev/null
done
awk 'NF >= 3 && $1 !~ /^#/ { printf "%s %.7f %.7f\n", $1, -$2, -$3 }' \
  active/MILL-3/Y.txt > "$scratch/y-negated.txt"
axcheck simulate models/mill3-x.yaml --seed 3011 --controller linuxcnc \
  --active active/MILL-3/X.txt -o data/mill3-x.csv
axcheck simulate models/mill3-y.yaml --seed 3021 --controller linuxcnc \
  --active "$scratch/y-negated.txt" -o data/mill3-y.csv
