#!/usr/bin/env bash
# Installs the Debian 12 packages that fogbench needs to build, run and test,
# then makes sure Qwt for Qt 6 is there (scripts/setup-qwt-qt6.sh: Debian 12
# packages Qwt only for Qt 5, so it is built once, static, into
# /opt/fogbench-qwt-qt6). The GUI builds on Qt 6 by default; Qt 5.15 + Qwt 6.1
# stay installed for the Qt 5 build (CI builds and tests both) and as the
# fallback when Qt 6 or its Qwt cannot be had.
# Idempotent: packages already present are left alone and nothing is fetched
# when everything is installed. Must run as root (or with sudo available).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

packages=(
  build-essential cmake ninja-build pkg-config git ccache
  libeigen3-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
  qtbase5-dev libqt5svg5-dev libqt5opengl5-dev
  libqwt-qt5-dev libsqlite3-dev sqlite3 qttools5-dev qttools5-dev-tools
  qt6-base-dev qt6-base-dev-tools qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools
  qt6-l10n-tools qt6-qpa-plugins qmake6 libgl-dev bzip2
  clang libclang-rt-14-dev
  xvfb xauth openbox fonts-wqy-microhei
  python3 python3-numpy python3-h5py
  libhdf5-dev
  libpq-dev postgresql-15
  poppler-utils
  qt6-translations-l10n qttranslations5-l10n
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all ${#packages[@]} required Debian packages are installed"
  exec "$here/setup-qwt-qt6.sh"
fi

echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  apt_get=(apt-get)
elif command -v sudo >/dev/null 2>&1; then
  apt_get=(sudo apt-get)
else
  echo "setup: need root to install packages. Run as root, or install them yourself:" >&2
  echo "  apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${apt_get[@]}" update -qq
if ! "${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"; then
  # Without Qt 6 the GUI builds on Qt 5 (cmake/FogQt.cmake says so).
  without_qt6=()
  for p in "${missing[@]}"; do [[ $p == qt6-* || $p == qmake6 ]] || without_qt6+=("$p"); done
  echo "setup: installing failed; retrying without the Qt 6 packages (the GUI then builds on Qt 5 + Qwt 6.1)" >&2
  "${apt_get[@]}" install -y -qq --no-install-recommends "${without_qt6[@]}"
fi
echo "setup: packages done"
exec "$here/setup-qwt-qt6.sh"
