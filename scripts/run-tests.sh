#!/usr/bin/env bash
# Set up, build and run every test, each test once per build flavour that it
# proves something in (docs/benchmarks.md, "CI and the first result", has the
# stage times):
#   release   the full build (core, CLI, GUI on Qt 6 + Qwt 6.3) and every test;
#   qt5       the GUI and its UI tests on Qt 5.15 + Qwt 6.1 (only the GUI's
#             targets, only the `ui` and `translations` tests), so both Qt
#             majors keep building and passing;
#   headless  core and the CLI built without Qt, and the CLI's tests on that
#             build (core's own suites test the same code and ran in release);
#   asan      AddressSanitizer + UndefinedBehaviorSanitizer (-O1 -g1): every
#             test but the labels independent, memory_budget, desk, python,
#             package, statistics and scenario (Monte Carlo trials and the
#             diagnosis' named-effect cases: the same code paths as the cases
#             kept, at 5 times the cost), and any sanitizer report fails the run;
#   fuzz      the libFuzzer targets for a bounded time each (FUZZ_SECONDS,
#             default 60), two at a time on the two cores.
# ccache, when installed, is the compiler launcher, so later legs reuse the
# objects earlier ones (and earlier runs) made. At the end (or at a failure)
# the time of each stage is printed beside its budget: 30 min in all on two
# cores with a warm ccache.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's heading says how long the run has taken so far; the summary
# at exit gives each stage's time against its budget (minutes).
stage_names=() stage_starts=() stage_budgets=()
stage() {
  local budget=$1; shift
  stage_names+=("$*") stage_starts+=("$SECONDS") stage_budgets+=("$budget")
  echo "== $* [$((SECONDS / 60)) min $((SECONDS % 60)) s] =="
}
summary() {
  local status=$? i end took over=""
  echo "== stage times (budget) =="
  for i in "${!stage_names[@]}"; do
    (( stage_budgets[i] > 0 )) || continue
    end=$SECONDS
    (( i + 1 < ${#stage_starts[@]} )) && end=${stage_starts[i + 1]}
    took=$(( end - stage_starts[i] ))
    over=""
    (( took > stage_budgets[i] * 60 )) && over="  over budget"
    printf '  %-10s %3d min %02d s  (budget %2d min)%s\n' "${stage_names[i]%%:*}" $((took / 60)) $((took % 60)) \
      "${stage_budgets[i]}" "$over"
  done
  printf '  %-10s %3d min %02d s  (budget 30 min)%s\n' "all" $((SECONDS / 60)) $((SECONDS % 60)) \
    "$( (( SECONDS > 1800 )) && echo "  over budget")"
  [[ $status == 0 ]] || echo "!! the run failed (exit $status) in stage: ${stage_names[-1]:-setup}" >&2
}
trap summary EXIT

stage 1 "setup: Debian packages and Qwt for Qt 6 (scripts/setup.sh)"
./scripts/setup.sh

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  # The asan and fuzz legs build with debug info, which ccache would key on
  # the build folder's path: a clone elsewhere (CI's clean clone) would then
  # miss every object. Their paths are relative (CCACHE_BASEDIR) anyway.
  export CCACHE_NOHASHDIR=1
fi

# Prints the Qt + Qwt pair a configured build tree uses.
qt_of() { sed -n 's/^-- fogbench: GUI uses //p' "$1"; }
mkdir -p build

stage 14 "release: the full build, Qt 6 + Qwt >= 6.2 by default, every test"
cmake --preset release "${launcher[@]}" | tee build/.configure-release.log
echo "== release build's GUI: $(qt_of build/.configure-release.log) =="
if ! qt_of build/.configure-release.log | grep -q '^Qt 6'; then
  echo "!! WARNING: the release build fell back to Qt 5 (no Qt 6 or no Qwt for Qt 6; see setup's and configure's messages above): Qt 6 is not tested in this run" >&2
fi
cmake --build --preset release
ctest --preset release --output-on-failure -j2

stage 2 "qt5: the GUI and its UI tests on Qt 5.15 + Qwt 6.1"
cmake --preset qt5 "${launcher[@]}" | tee build/.configure-qt5.log
echo "== Qt 5 build's GUI: $(qt_of build/.configure-qt5.log) =="
cmake --build --preset qt5
ctest --preset qt5 --output-on-failure -j2

stage 1 "headless: core and the CLI without Qt, the CLI's tests"
# What only this leg shows: core and the command line build and pass their
# tests without Qt. Core's GoogleTest suites are not built here (the preset's
# FOG_BUILD_CORE_TESTS=OFF): the same code ran them in the release leg; nor
# does the test preset run the labels independent and memory_budget.
cmake --preset headless "${launcher[@]}"
cmake --build --preset headless
ctest --preset headless --output-on-failure -j2

stage 9 "asan: every test but the labels independent, memory_budget, desk, python, package, statistics and scenario under ASan + UBSan"
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

stage 3 "fuzz: sampling-board decoder, session reader, CSV import and plan JSON, analysis with numeric extremes, table SCPI (libFuzzer + ASan/UBSan, clang)"
# Bounded: FUZZ_SECONDS each (default 60), two targets at a time (each
# fuzzer is one process on one core). Seeds: the committed decoder corpus
# and small simulated streams and sessions written by fog_fuzz_seed_corpus.
# A crash fails the run and leaves its input in the scratch folder printed
# below (docs/reliability.md); each fuzzer's output goes to a log there,
# printed when it ends.
fuzz_seconds="${FUZZ_SECONDS:-60}"
cmake --preset fuzz "${launcher[@]}"
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
# fuzz NAME SECONDS [libFuzzer options and corpus folders...]: runs in the
# background, its output in $fuzz_dir/NAME.log.
fuzz_pids=() fuzz_logs=()
fuzz() {
  local name=$1 seconds=$2; shift 2
  build/fuzz/fuzz/fog_fuzz_"$name" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$fuzz_dir/$name-" "$@" >"$fuzz_dir/$name.log" 2>&1 &
  fuzz_pids+=("$!") fuzz_logs+=("$fuzz_dir/$name.log")
}
# Waits for the fuzzers started since the last call; prints their logs'
# final statistics (all of a log when its fuzzer failed); fails on a failure.
fuzz_wait() {
  local i failed=0
  for i in "${!fuzz_pids[@]}"; do
    if wait "${fuzz_pids[i]}"; then
      echo "-- ${fuzz_logs[i]##*/}:"; grep -E '^(stat::|Done|INFO: Seed)' "${fuzz_logs[i]}" || true
    else
      echo "!! fuzzer failed: ${fuzz_logs[i]}" >&2; cat "${fuzz_logs[i]}" >&2; failed=1
    fi
  done
  fuzz_pids=() fuzz_logs=()
  return "$failed"
}
half=$(( (fuzz_seconds + 1) / 2 ))
fuzz decoder "$fuzz_seconds" "$fuzz_dir/decoder" fuzz/corpus/decoder "$fuzz_dir/seed-decoder"
fuzz session "$fuzz_seconds" "$fuzz_dir/session" "$fuzz_dir/seed-session"
fuzz_wait
fuzz import "$fuzz_seconds" -max_len=65536 "$fuzz_dir/import" "$fuzz_dir/seed-import" fuzz/corpus/import
# The analysis over recordings with numeric extremes (committed seeds: ±1e±300,
# subnormals, NaN, inf, huge counts), then the table's SCPI parser and
# emulated controller (a small parser): half the time each, one after the other.
( build/fuzz/fuzz/fog_fuzz_analysis -max_total_time="$half" -print_final_stats=1 -max_len=512 \
    -artifact_prefix="$fuzz_dir/analysis-" "$fuzz_dir/analysis" fuzz/corpus/analysis &&
  build/fuzz/fuzz/fog_fuzz_scpi -max_total_time="$half" -print_final_stats=1 -max_len=4096 \
    -artifact_prefix="$fuzz_dir/scpi-" "$fuzz_dir/scpi" fuzz/corpus/scpi ) >"$fuzz_dir/analysis-scpi.log" 2>&1 &
fuzz_pids+=("$!") fuzz_logs+=("$fuzz_dir/analysis-scpi.log")
fuzz_wait
stage 0 "done: release (Qt 6), Qt 5, headless, asan and fuzzing all passed"
