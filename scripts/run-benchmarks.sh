#!/usr/bin/env bash
# Builds the Release benchmarks and runs them: analysis and simulator
# (fog_bench_analysis), decoder (fog_bench_decoder), session files
# (fog_bench_session), CSV import/export (fog_bench_io), gyro noise
# (fog_bench_noise), sim-to-real diagnosis (fog_bench_diagnosis). Figures: docs/benchmarks.md.
# Extra arguments go to every program (e.g. --benchmark_repetitions=5).
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release --target fog_bench_analysis fog_bench_decoder fog_bench_session fog_bench_io fog_bench_noise fog_bench_diagnosis
echo "== $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1), Release =="
build/release/bench/fog_bench_analysis "$@"
build/release/bench/fog_bench_decoder "$@"
build/release/bench/fog_bench_session "$@"
build/release/bench/fog_bench_io "$@"
build/release/bench/fog_bench_noise "$@"
build/release/bench/fog_bench_diagnosis "$@"
