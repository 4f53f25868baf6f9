#!/usr/bin/env bash
# The catalog and batch benchmarks on the user's path (docs/benchmarks.md,
# "The catalog"): fogbench-cli as a lab runs it, wall time and peak RSS.
#   bench/catalog_bench.sh BUILD_DIR SCRATCH [N=1000] [M=10000]
# 1. N 4.9-min sessions (paper-slow, 27.7 MB each, one stored result; made by
#    fog_make_sessions under eatmydata when installed: their fsyncs are the
#    input's making, not what is measured);
# 2. catalog index of the folder (first time), then again unchanged;
# 3. batch re-analysis of the N with 2 jobs (the catalog updated after);
# 4. M short sessions (8 s), indexed, then re-scanned unchanged.
# Needs about N x 28 MB + M x 1 MB of free disk in SCRATCH; removes them after.
set -euo pipefail
build=$1 scratch=$2 n=${3:-1000} m=${4:-10000}
cli=$build/app/fogbench-cli make=$build/bench/fog_make_sessions
nosync=(); command -v eatmydata >/dev/null && nosync=(eatmydata)
measure() {  # label, command...: prints "label: wall s, peak RSS MB"
  local label=$1; shift
  /usr/bin/time -f "%e %M" -o "$scratch/time" "$@" > "$scratch/out" 2>&1 || { cat "$scratch/out"; exit 1; }
  read -r wall rss < "$scratch/time"
  printf '%-52s %8.2f s wall  %6.0f MB peak RSS\n' "$label" "$wall" "$((rss / 1024))"
  tail -n 3 "$scratch/out" | sed 's/^/      /'
}
mkdir -p "$scratch"
rm -rf "$scratch/long" "$scratch/short"
half=$(( n / 2 ))
measure "make $n 4.9-min sessions (2 processes)" bash -c "
  ${nosync[*]} $make $scratch/long $half paper-slow 1 & ${nosync[*]} $make $scratch/long $(( n - half )) paper-slow $(( half + 1 )); wait"
echo "      $(du -sh "$scratch/long" | cut -f1) on disk"
measure "catalog index, $n sessions, first time" "$cli" catalog index "$scratch/long"
measure "catalog index, $n sessions, unchanged" "$cli" catalog index "$scratch/long"
measure "batch --jobs 2, $n sessions (+ catalog update)" "$cli" batch "$scratch/long" --jobs 2 \
  --jsonl "$scratch/batch.jsonl" --read-delay-ms 0.06
measure "catalog lot L01 (40 units)" "$cli" catalog lot L01 --db "$scratch/long"
rm -rf "$scratch/long" "$scratch/batch.jsonl"
half=$(( m / 2 ))
measure "make $m short sessions (2 processes)" bash -c "
  ${nosync[*]} $make $scratch/short $half short 1 & ${nosync[*]} $make $scratch/short $(( m - half )) short $(( half + 1 )); wait"
measure "catalog index, $m sessions, first time" "$cli" catalog index "$scratch/short"
measure "catalog index, $m sessions, unchanged (re-scan)" "$cli" catalog index "$scratch/short"
rm -rf "$scratch/short"
