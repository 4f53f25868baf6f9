#!/usr/bin/env bash
# Set up, build and run every test: the full build (core, CLI, GUI on Qt 6 +
# Qwt 6.3) through CTest; the GUI and its UI tests again on Qt 5.15 + Qwt 6.1
# (the `qt5` preset: only the GUI's targets, only the `ui` and `translations`
# tests), so both Qt majors keep building and passing; a headless build
# without Qt, which proves core/ and the CLI need no Qt, and runs its core
# and CLI tests again (not the independent suite: the release leg ran it); a build with AddressSanitizer + UndefinedBehaviorSanitizer (the
# `asan` preset) runs every test but the label `independent` again, and any
# sanitizer report fails the run; last, the libFuzzer targets run for a
# bounded time each (FUZZ_SECONDS, default 60). ccache, when installed, is the compiler
# launcher, so the Qt 5 and headless legs reuse the release leg's Qt-free
# objects.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's heading says how long the run has taken so far.
stage() { echo "== $* [$((SECONDS / 60)) min $((SECONDS % 60)) s] =="; }

./scripts/setup.sh

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
fi

# Prints the Qt + Qwt pair a configured build tree uses.
qt_of() { sed -n 's/^-- fogbench: GUI uses //p' "$1"; }
mkdir -p build

stage "full build (release): Qt 6 + Qwt >= 6.2 by default"
cmake --preset release "${launcher[@]}" | tee build/.configure-release.log
echo "== release build's GUI: $(qt_of build/.configure-release.log) =="
if ! qt_of build/.configure-release.log | grep -q '^Qt 6'; then
  echo "!! WARNING: the release build fell back to Qt 5 (no Qt 6 or no Qwt for Qt 6; see setup's and configure's messages above): Qt 6 is not tested in this run" >&2
fi
cmake --build --preset release
ctest --preset release --output-on-failure -j2

stage "Qt 5 build: GUI and UI tests on Qt 5.15 + Qwt 6.1 (preset qt5)"
cmake --preset qt5 "${launcher[@]}" | tee build/.configure-qt5.log
echo "== Qt 5 build's GUI: $(qt_of build/.configure-qt5.log) =="
cmake --build --preset qt5
ctest --preset qt5 --output-on-failure -j2

stage "headless build: core and CLI only, no Qt"
# What only this leg shows: core and the command line build and pass their
# tests without Qt. The independent suite (label `independent`) checks the
# same core code against an independent generator and already ran in the
# release leg: it is not run twice.
cmake --preset headless "${launcher[@]}"
cmake --build --preset headless
ctest --preset headless --output-on-failure -j2 -LE independent

stage "sanitizers: every test but the label independent under ASan + UBSan (preset asan)"
# The preset's environment sets the sanitizer options and tests/lsan.supp
# (Qt 5's offscreen leaks; nothing is suppressed on Qt 6). A report must fail
# the run even from a process whose failure a test expects (a CLI error path
# exits non-zero anyway) or whose output it does not show, so ASan and LSan
# write their reports to files in a scratch folder, checked after the tests.
# UBSan ignores log_path in GCC's combined runtime: it stops the process
# (halt_on_error=1), and its "runtime error:" lines are looked for in the full
# output of every test (Testing/Temporary/LastTest.log). docs/reliability.md.
cmake --preset asan "${launcher[@]}" | tee build/.configure-asan.log
echo "== asan build's GUI: $(qt_of build/.configure-asan.log) =="
cmake --build --preset asan
asan_dir="$(mktemp -d /tmp/fogbench-asan.XXXXXX)"
echo "sanitizer reports go to: $asan_dir"
asan_failed=0
ASAN_OPTIONS="log_path=$asan_dir/report" ctest --preset asan --output-on-failure -j2 || asan_failed=1
for report in "$asan_dir"/report.*; do
  [ -e "$report" ] || continue
  echo "!! sanitizer report $report:" >&2
  cat "$report" >&2
  asan_failed=1
done
if grep -n -E 'runtime error:|ERROR: (Address|Leak)Sanitizer' build/asan/Testing/Temporary/LastTest.log >&2; then
  echo "!! sanitizer reports in the tests' output (build/asan/Testing/Temporary/LastTest.log)" >&2
  asan_failed=1
fi
if [ "$asan_failed" != 0 ]; then
  echo "!! the asan stage failed: see the failed tests and the sanitizer reports above" >&2
  exit 1
fi

stage "fuzzing: sampling-board decoder, session reader, CSV import and plan JSON, analysis with numeric extremes, table SCPI (libFuzzer + ASan/UBSan, clang)"
# Bounded: FUZZ_SECONDS each (default 60). Seeds: the committed decoder corpus
# and small simulated streams and sessions written by fog_fuzz_seed_corpus.
# A crash fails the run and leaves its input in the scratch folder printed
# below (docs/reliability.md).
fuzz_seconds="${FUZZ_SECONDS:-60}"
cmake --preset fuzz
cmake --build --preset fuzz --target fog_fuzz_decoder fog_fuzz_session fog_fuzz_import fog_fuzz_analysis fog_fuzz_scpi fog_fuzz_seed_corpus
fuzz_dir="$(mktemp -d /tmp/fogbench-fuzz.XXXXXX)"
echo "fuzz scratch: $fuzz_dir"
mkdir -p "$fuzz_dir"/{seed-decoder,seed-session,seed-import,decoder,session,import,analysis,scpi}
# Import seed: a plan, a metadata text, a table and a gyro file, NUL-separated.
printf '%s\0%s\0%s\0%s' \
  '{"rest_between_s": 1, "points": [{"axis": "x", "frequency_hz": 1, "amplitude_deg": 3, "duration_s": 10}]}' \
  '{"bench": {"table_read_delay_ms": 0.05, "board_delay_ms": 0.28, "pulse_equivalent_deg": 5e-5, "gyro_sign": {"x": -1}}, "test_points": [{"axis": "x", "frequency_hz": 1}]}' \
  "$(printf 'time_s,x_deg\n0.001,0.1\n0.002,0.2\n0.003,0.3\n')" \
  "$(printf 'test_point,time_s,x_inc_deg,lost_before\n1,0.002,0.001,0\n1,0.004,0.002,1\n')" > "$fuzz_dir/seed-import/one"
build/fuzz/fuzz/fog_fuzz_seed_corpus "$fuzz_dir/seed-decoder" "$fuzz_dir/seed-session"
build/fuzz/fuzz/fog_fuzz_decoder -max_total_time="$fuzz_seconds" -print_final_stats=1 \
  -artifact_prefix="$fuzz_dir/decoder-" "$fuzz_dir/decoder" fuzz/corpus/decoder "$fuzz_dir/seed-decoder"
build/fuzz/fuzz/fog_fuzz_session -max_total_time="$fuzz_seconds" -print_final_stats=1 \
  -artifact_prefix="$fuzz_dir/session-" "$fuzz_dir/session" "$fuzz_dir/seed-session"
build/fuzz/fuzz/fog_fuzz_import -max_total_time="$fuzz_seconds" -print_final_stats=1 -max_len=65536 \
  -artifact_prefix="$fuzz_dir/import-" "$fuzz_dir/import" "$fuzz_dir/seed-import" fuzz/corpus/import
# The analysis over recordings with numeric extremes (committed seeds: ±1e±300,
# subnormals, NaN, inf, huge counts): half the time (each input is a whole analysis).
build/fuzz/fuzz/fog_fuzz_analysis -max_total_time="$(( (fuzz_seconds + 1) / 2 ))" -print_final_stats=1 -max_len=512 \
  -artifact_prefix="$fuzz_dir/analysis-" "$fuzz_dir/analysis" fuzz/corpus/analysis
# The table's SCPI parser and emulated controller: half the time (a small parser).
build/fuzz/fuzz/fog_fuzz_scpi -max_total_time="$(( (fuzz_seconds + 1) / 2 ))" -print_final_stats=1 -max_len=4096 \
  -artifact_prefix="$fuzz_dir/scpi-" "$fuzz_dir/scpi" fuzz/corpus/scpi
stage "done: release (Qt 6), Qt 5, headless, asan and fuzzing all passed"
