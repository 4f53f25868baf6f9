#!/bin/sh
# Runs a test program in a real X server with a window manager (issue 31):
# Xvfb with one screen of SIZE (e.g. 1366x768) and openbox, the language in
# FOG_DESK_LANGUAGE. Both are installed by scripts/setup.sh; missing, the
# test fails and says so (it is never skipped).
#   run_desk_test.sh SIZE LANGUAGE PROGRAM [ARGS...]
set -u
size=$1
language=$2
shift 2
for tool in Xvfb openbox; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "run_desk_test: $tool is missing: install it (scripts/setup.sh installs xvfb and openbox)" >&2
    exit 1
  fi
done
scratch=$(mktemp -d /tmp/fogbench-desk.XXXXXX)
xvfb=""
wm=""
# Whatever ends the test (a CTest timeout's kill too), the X server and the
# window manager go with it.
cleanup() {
  [ -n "$wm" ] && kill "$wm" 2>/dev/null
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null
  rm -rf "$scratch"
}
trap cleanup EXIT
trap 'exit 143' INT TERM
# Xvfb picks a free display and writes its number.
Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp 3>"$scratch/display" >"$scratch/xvfb.log" 2>&1 &
xvfb=$!
for _ in $(seq 1 100); do
  [ -s "$scratch/display" ] && break
  sleep 0.1
done
if [ ! -s "$scratch/display" ]; then
  echo "run_desk_test: Xvfb did not start:" >&2
  cat "$scratch/xvfb.log" >&2
  exit 1
fi
DISPLAY=":$(cat "$scratch/display")"
export DISPLAY
openbox --sm-disable >"$scratch/openbox.log" 2>&1 &
wm=$!
sleep 1
QT_QPA_PLATFORM=xcb FOG_DESK_LANGUAGE="$language" "$@"
exit $?
