#!/usr/bin/env bash
# Installs the Debian 12 packages that fogbench needs to build, run and test.
# Idempotent: packages already present are left alone and nothing is fetched
# when everything is installed. Must run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
  qtbase5-dev libqt5svg5-dev libqt5opengl5-dev libqt5serialport5-dev
  libqwt-qt5-dev libsqlite3-dev qttools5-dev qttools5-dev-tools
  clang libclang-rt-14-dev
  xvfb xauth fonts-wqy-microhei
  python3 python3-numpy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all ${#packages[@]} required Debian packages are installed"
  exit 0
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
"${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
