#!/usr/bin/env bash
# Set up, build and run every test: the full build (core, CLI, GUI) through
# CTest, then a headless build without Qt, which proves core/ and the CLI need
# no Qt, and runs its core tests again.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh

echo "== full build (release) =="
cmake --preset release
cmake --build --preset release
ctest --preset release --output-on-failure -j2

echo "== headless build: core and CLI only, no Qt =="
cmake --preset headless
cmake --build --preset headless
ctest --preset headless --output-on-failure -j2
