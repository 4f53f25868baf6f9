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
cmake --preset release >/dev/null
cmake --build --preset release

if [[ $headless -eq 0 && ( -n ${DISPLAY:-} || -n ${WAYLAND_DISPLAY:-} ) && -x build/release/app/fogbench ]]; then
  # The paper's plan at real time unless asked otherwise: the window would
  # otherwise run the plan and pace it remembers from the last session.
  gui=(--run)
  [[ " ${args[*]-} " == *" --preset"* ]] || gui+=(--preset paper)
  [[ " ${args[*]-} " == *" --speed"* ]] || gui+=(--speed 1)
  exec build/release/app/fogbench "${gui[@]}" "${args[@]}"
fi
exec build/release/app/fogbench-cli run "${args[@]}"
