#!/usr/bin/env bash
# Fleet benchmark: generates synthetic campaigns of 1 000 and 10 000 axes and measures the
# median wall time and peak memory of `check` on both and of `run` (with every PDF) on
# 1 000, with --jobs 1 and with all cores. Prints a table and writes bench/results.md.
#
#   bash bench/fleet.sh            # default: 5 runs of check, 3 of run
#   RUNS=3 PDF_RUNS=1 bash bench/fleet.sh
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${RUNS:-5}
PDF_RUNS=${PDF_RUNS:-3}
WORK=${BENCH_DIR:-${TMPDIR:-/tmp}/axcheck-fleet}

if [ -z "${CARGO_TARGET_DIR:-}" ] && [ -d /work/cargo-target ]; then
  export CARGO_TARGET_DIR=/work/cargo-target
fi
if [ ! -x /usr/bin/time ]; then
  apt-get install -y -qq time >/dev/null 2>&1 || { echo "bench: GNU time (/usr/bin/time) is needed" >&2; exit 1; }
fi
cargo build --release --quiet
BIN=${CARGO_TARGET_DIR:-target}/release/axcheck
CORES=$(nproc)

for n in 1000 10000; do
  if [ ! -f "$WORK/f$n/campaign.yaml" ]; then
    "$BIN" simulate --fleet "$n" --seed 1 --out "$WORK/f$n"
  fi
done

# measure LABEL RUNS CMD… → "median_wall_s peak_rss_mb"
measure() {
  local runs=$1; shift
  local walls=() rss=0
  for _ in $(seq "$runs"); do
    rm -rf "$WORK/out"
    /usr/bin/time -f "%e %M" -o "$WORK/time.txt" "$@" >/dev/null 2>&1 || true
    # GNU time writes "Command exited with non-zero status 1" first when a campaign
    # has failing axes (exit 1 is expected here): the numbers are on the last line.
    read -r wall kb < <(tail -n 1 "$WORK/time.txt")
    walls+=("$wall")
    [ "$kb" -gt "$rss" ] && rss=$kb
  done
  local median
  median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}')
  echo "$median $((rss / 1024))"
}

rows=()
row() {
  local what=$1 axes=$2 jobs=$3 runs=$4; shift 4
  read -r wall mb < <(measure "$runs" "$@")
  rows+=("| $what | $axes | $jobs | $wall | $mb | $runs |")
  echo "$what axes=$axes jobs=$jobs: median ${wall} s, peak ${mb} MB ($runs runs)" >&2
}

for n in 1000 10000; do
  row check "$n" 1 "$RUNS" "$BIN" check "$WORK/f$n/campaign.yaml" --jobs 1
  row check "$n" "$CORES" "$RUNS" "$BIN" check "$WORK/f$n/campaign.yaml" --jobs "$CORES"
done
row "run (PDFs)" 1000 1 "$PDF_RUNS" "$BIN" run "$WORK/f1000/campaign.yaml" --out "$WORK/out" --jobs 1
row "run (PDFs)" 1000 "$CORES" "$PDF_RUNS" "$BIN" run "$WORK/f1000/campaign.yaml" --out "$WORK/out" --jobs "$CORES"

readings_1k=$(grep -c . "$WORK"/f1000/data/*/*.csv | awk -F: '{s += $2 - 1} END {print s}')
{
  echo "# Fleet benchmark"
  echo
  echo "Machine: $CORES cores, $(uname -m), $(date -u +%Y-%m-%d). Median wall time and peak resident memory of"
  echo "\`axcheck check\` / \`axcheck run\` (all outputs including one PDF per axis and the summary PDF)"
  echo "on synthetic fleets from \`axcheck simulate --fleet N --seed 1\` (1 000 axes: $readings_1k readings)."
  echo
  echo "| command | axes | --jobs | median wall (s) | peak memory (MB) | runs |"
  echo "|---|---:|---:|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
} > bench/results.md
cat bench/results.md
