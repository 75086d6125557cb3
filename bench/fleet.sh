#!/usr/bin/env bash
# Fleet benchmark: generates synthetic campaigns of 1 000 and 10 000 axes and measures the
# median wall time and peak memory of `check` on both and of `run` (with every PDF) on
# 1 000, with --jobs 1 and with all cores; of `trend` on ten yearly inspections of the
# 10 000 axes; and of a peer, the ISO 230-2 evaluation of the same files scripted with
# pandas and numpy (bench/peer_iso230_2.py), run in turn with `check` so that their ratio
# is taken pair by pair in one run; and of the axis reports against a matplotlib peer
# (bench/peer_report.py, 200 axes, CPU time). BIG=1 adds 100 000 axes (check, run
# --no-pdf). Prints a table and writes its part of bench/results.md (between the markers).
#
#   bash bench/fleet.sh            # default: 5 runs of check, 3 of run and trend, 5 pairs
#                                  # with the evaluation's peer, 3 with the reports' peer
#   RUNS=3 PDF_RUNS=1 PEER_RUNS=1 PDF_PEER_RUNS=1 bash bench/fleet.sh
#   PYTHON=/path/to/venv/bin/python bash bench/fleet.sh   # the peers' Python
#   BASELINE=/path/to/old/axcheck bash bench/fleet.sh   # also: this build against another
#     (check on 10 000 axes and run with PDFs on 1 000, in turn, the ratio pair by pair)
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${RUNS:-5}
PDF_RUNS=${PDF_RUNS:-3}
PEER_RUNS=${PEER_RUNS:-5}
PDF_PEER_RUNS=${PDF_PEER_RUNS:-3}
# The Python of the peers (pandas, numpy; matplotlib and PyYAML for the reports' peer).
PYTHON=${PYTHON:-python3}
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

for n in 200 1000 10000 ${BIG:+100000}; do
  if [ ! -f "$WORK/f$n/campaign.yaml" ]; then
    "$BIN" simulate --fleet "$n" --seed 1 --out "$WORK/f$n"
  fi
done

# measure RUNS CMD… → "median_wall_s peak_rss_mb median_cpu_s" (CPU: user + system)
measure() {
  local runs=$1; shift
  local walls=() cpus=() rss=0
  for _ in $(seq "$runs"); do
    rm -rf "$WORK/out" "$WORK/peer-out"
    /usr/bin/time -f "%e %M %U %S" -o "$WORK/time.txt" "$@" >/dev/null 2>&1 || true
    # GNU time writes "Command exited with non-zero status 1" first when a campaign
    # has failing axes (exit 1 is expected here): the numbers are on the last line.
    read -r wall kb user sys < <(tail -n 1 "$WORK/time.txt")
    walls+=("$wall")
    cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN {printf "%.2f", u + s}')")
    [ "$kb" -gt "$rss" ] && rss=$kb
  done
  local mid='{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'
  echo "$(printf '%s\n' "${walls[@]}" | sort -g | awk "$mid") $((rss / 1024)) $(printf '%s\n' "${cpus[@]}" | sort -g | awk "$mid")"
}

# ratio A B → A / B to one decimal
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f", a / b}'; }

rows=()
row() {
  local what=$1 axes=$2 jobs=$3 runs=$4; shift 4
  read -r wall mb _ < <(measure "$runs" "$@")
  rows+=("| $what | $axes | $jobs | $wall | $mb | $runs |")
  echo "$what axes=$axes jobs=$jobs: median ${wall} s, peak ${mb} MB ($runs runs)" >&2
}

for n in 1000 10000; do
  row check "$n" 1 "$RUNS" "$BIN" check "$WORK/f$n/campaign.yaml" --jobs 1
  row check "$n" "$CORES" "$RUNS" "$BIN" check "$WORK/f$n/campaign.yaml" --jobs "$CORES"
done
row "run (PDFs)" 1000 1 "$PDF_RUNS" "$BIN" run "$WORK/f1000/campaign.yaml" --out "$WORK/out" --jobs 1
row "run (PDFs)" 1000 "$CORES" "$PDF_RUNS" "$BIN" run "$WORK/f1000/campaign.yaml" --out "$WORK/out" --jobs "$CORES"

# Ten yearly inspections of the 10 000 axes (the campaign's date moved a year each time),
# made once: the history `trend` reads.
if [ ! -f "$WORK/history.done" ]; then
  rm -rf "$WORK/history" "$WORK/hout"
  for year in $(seq 2017 2026); do
    sed "s/date: 2026-11-20/date: $year-11-20/" "$WORK/f10000/campaign.yaml" > "$WORK/f10000/campaign-$year.yaml"
    "$BIN" run "$WORK/f10000/campaign-$year.yaml" --out "$WORK/hout" --no-pdf --no-html --no-diagnose \
      --history "$WORK/history" >/dev/null 2>&1 || true
  done
  touch "$WORK/history.done"
fi
row "trend (10 inspections)" 10000 "$CORES" "$PDF_RUNS" "$BIN" trend "$WORK/history" --json

# The peer and check in turn, on the same files: the ratio of each pair, then the median.
"$PYTHON" -c 'import pandas, numpy' 2>/dev/null || "$PYTHON" -m pip install --quiet pandas numpy
peer_rows=()
peer_walls=()
for n in 1000 10000; do
  ratios=()
  for _ in $(seq "$PEER_RUNS"); do
    read -r ours _ < <(measure 1 "$BIN" check "$WORK/f$n/campaign.yaml" --jobs "$CORES")
    read -r peer mb _ < <(measure 1 "$PYTHON" bench/peer_iso230_2.py "$WORK/f$n/data" --jobs "$CORES")
    ratios+=("$(ratio "$peer" "$ours")")
    peer_walls+=("$peer")
  done
  sorted=$(printf '%s\n' "${ratios[@]}" | sort -g)
  ratio=$(echo "$sorted" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  worst=$(echo "$sorted" | head -n 1)
  wall=$(printf '%s\n' "${peer_walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  peer_walls=()
  peer_rows+=("| pandas + numpy peer | $n | $CORES | $wall | $mb | $PEER_RUNS | ${ratios[*]/%/×} | $ratio× | $worst× |")
  echo "peer axes=$n: median ${wall} s; the peer's time / check's, pair by pair: ${ratios[*]} (worst $worst)" >&2
done

# The axis reports: `run --no-diagnose --no-html` on 200 axes and the matplotlib peer
# (bench/peer_report.py) in turn; the ratio of their CPU times (user + system), pair by pair.
pdf_rows=()
if "$PYTHON" -c 'import matplotlib, yaml' 2>/dev/null || "$PYTHON" -m pip install --quiet matplotlib pyyaml; then
  ratios=()
  for _ in $(seq "$PDF_PEER_RUNS"); do
    read -r ours_wall _ ours < <(measure 1 "$BIN" run "$WORK/f200/campaign.yaml" --no-diagnose --no-html --out "$WORK/out" --jobs "$CORES")
    read -r peer_wall _ peer < <(measure 1 "$PYTHON" bench/peer_report.py "$WORK/f200/data" "$WORK/peer-out" --jobs "$CORES")
    ratios+=("$(ratio "$peer" "$ours")")
    pdf_rows+=("| $ours | $ours_wall | $peer | $peer_wall | $(ratio "$peer" "$ours")× |")
  done
  echo "PDFs of 200 axes: the peer's CPU / run's, pair by pair: ${ratios[*]}" >&2
fi

# 100 000 axes (BIG=1): check and run --no-pdf against 10 000 axes, in turn.
big_rows=()
if [ -n "${BIG:-}" ]; then
  for what in check run; do
    for n in 10000 100000; do
      case $what in
        check) read -r wall mb cpu < <(measure 1 "$BIN" check "$WORK/f$n/campaign.yaml" --jobs "$CORES") ;;
        run) read -r wall mb cpu < <(measure 1 "$BIN" run "$WORK/f$n/campaign.yaml" --no-pdf --out "$WORK/out" --jobs "$CORES") ;;
      esac
      big_rows+=("| $what | $n | $wall | $cpu | $mb |")
      echo "$what axes=$n: ${wall} s, ${cpu} s CPU, ${mb} MB" >&2
    done
  done
fi

# This build and a baseline build in turn on the same files: the ratio of each pair.
base_rows=()
if [ -n "${BASELINE:-}" ]; then
  base_pair() {
    local what=$1 axes=$2 runs=$3; shift 3
    local ratios=() ours_walls=() base_walls=() ours_mb=0 base_mb=0
    for _ in $(seq "$runs"); do
      read -r ours mb _ < <(measure 1 "$BIN" "$@")
      [ "$mb" -gt "$ours_mb" ] && ours_mb=$mb
      read -r base mb _ < <(measure 1 "$BASELINE" "$@")
      [ "$mb" -gt "$base_mb" ] && base_mb=$mb
      ours_walls+=("$ours"); base_walls+=("$base")
      ratios+=("$(awk -v a="$base" -v b="$ours" 'BEGIN {printf "%.2f", a / b}')")
    done
    local mid='{a[NR]=$1} END {print a[int((NR+1)/2)]}'
    local ratio ours_wall base_wall
    ratio=$(printf '%s\n' "${ratios[@]}" | sort -g | awk "$mid")
    ours_wall=$(printf '%s\n' "${ours_walls[@]}" | sort -g | awk "$mid")
    base_wall=$(printf '%s\n' "${base_walls[@]}" | sort -g | awk "$mid")
    base_rows+=("| $what | $axes | $base_wall | $base_mb | $ours_wall | $ours_mb | $runs | $ratio× |")
    echo "$what axes=$axes: baseline ${base_wall} s, this build ${ours_wall} s; baseline / this, pair by pair: median ${ratio}" >&2
  }
  base_pair check 10000 "$RUNS" check "$WORK/f10000/campaign.yaml" --jobs "$CORES"
  base_pair "run (PDFs)" 1000 "$PDF_RUNS" run "$WORK/f1000/campaign.yaml" --out "$WORK/out" --jobs "$CORES"
fi

readings_1k=$(grep -c . "$WORK"/f1000/data/*/*.csv | awk -F: '{s += $2 - 1} END {print s}')
# The generated part of bench/results.md, between its markers; what follows them is
# written by hand (one-off measurements) and kept.
generated=$(mktemp)
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
  echo
  echo "The peer (bench/peer_iso230_2.py: pandas reads each file, groups by target and direction,"
  echo "and computes ISO 230-2's A, E, M, R and B), run in turn with \`axcheck check --jobs $CORES\` on"
  echo "the same files; the last column is the peer's wall time over check's, the median of the pairs."
  echo
  echo "| command | axes | workers | median wall (s) | peak memory (MB) | pairs | peer / check, each pair | median | worst |"
  echo "|---|---:|---:|---:|---:|---:|---|---:|---:|"
  printf '%s\n' "${peer_rows[@]}"
  if [ ${#pdf_rows[@]} -gt 0 ]; then
    echo
    echo "The axis reports: \`axcheck run --no-diagnose --no-html --jobs $CORES\` on 200 axes (every"
    echo "axis report, the summary PDF and the tables) and the matplotlib peer (bench/peer_report.py:"
    echo "a two-page report per axis with its tables and the ISO 230-2 charts) with $CORES workers,"
    echo "in turn; CPU is user + system time, the ratio the peer's over axcheck's, pair by pair."
    echo
    echo "| axcheck CPU (s) | axcheck wall (s) | peer CPU (s) | peer wall (s) | peer / axcheck |"
    echo "|---:|---:|---:|---:|---:|"
    printf '%s\n' "${pdf_rows[@]}"
  fi
  if [ ${#big_rows[@]} -gt 0 ]; then
    echo
    echo "100 000 axes (\`BIG=1\`), one run each, in turn with 10 000:"
    echo
    echo "| command | axes | wall (s) | CPU (s) | peak memory (MB) |"
    echo "|---|---:|---:|---:|---:|"
    printf '%s\n' "${big_rows[@]}"
  fi
  if [ ${#base_rows[@]} -gt 0 ]; then
    echo
    echo "This build against the baseline \`$("$BASELINE" --version)\` ($BASELINE), run in turn on the"
    echo "same files with --jobs $CORES; the last column is the baseline's wall time over this build's,"
    echo "the median of the pairs."
    echo
    echo "| command | axes | baseline median wall (s) | baseline peak (MB) | this build (s) | this build peak (MB) | pairs | baseline / this |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
    printf '%s\n' "${base_rows[@]}"
  fi
} > "$generated"
python3 - "$generated" <<'PY'
import sys
begin, end = "<!-- fleet.sh: begin -->", "<!-- fleet.sh: end -->"
new = open(sys.argv[1], encoding="utf-8").read()
try:
    old = open("bench/results.md", encoding="utf-8").read()
except FileNotFoundError:
    old = ""
kept = old.split(end, 1)[1] if end in old else ""
open("bench/results.md", "w", encoding="utf-8").write(f"{begin}\n{new}{end}{kept}")
PY
rm -f "$generated"
cat bench/results.md
