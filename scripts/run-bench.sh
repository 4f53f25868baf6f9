#!/usr/bin/env bash
# The main job: set up, build, and run the bench on its built-in simulator.
# With a display, the desktop bench opens and runs the paper's test plan; with
# no display (or with --headless) the headless bench prints the delay report.
# Extra arguments go to `fogbench-cli run` (see `fogbench-cli help`).
set -euo pipefail
cd "$(dirname "$0")/.."

headless=0
args=()
for a in "$@"; do
  if [[ $a == --headless ]]; then headless=1; else args+=("$a"); fi
done

./scripts/setup.sh
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
fi
cmake --preset release "${launcher[@]}" >/dev/null

# Only what runs is built: the command-line bench, and the desktop bench when
# there is a display to show it on (and the build has a GUI). The tests and
# benchmarks are left to scripts/run-tests.sh; the README has the time.
window=0
if [[ $headless -eq 0 && ( -n ${DISPLAY:-} || -n ${WAYLAND_DISPLAY:-} ) ]] &&
   ninja -C build/release -t query fogbench >/dev/null 2>&1; then
  window=1
fi
targets=(fogbench-cli)
[[ $window -eq 1 ]] && targets+=(fogbench)
cmake --build --preset release --target "${targets[@]}"

if [[ $window -eq 1 ]]; then
  # The paper's plan at real time unless asked otherwise: the window would
  # otherwise run the plan and pace it remembers from the last session.
  gui=(--run)
  [[ " ${args[*]-} " == *" --preset"* ]] || gui+=(--preset paper)
  [[ " ${args[*]-} " == *" --speed"* ]] || gui+=(--speed 1)
  exec build/release/app/fogbench "${gui[@]}" "${args[@]}"
fi
exec build/release/app/fogbench-cli run "${args[@]}"
