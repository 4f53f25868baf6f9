#!/usr/bin/env bash
# Qwt for Qt 6, which Debian 12 does not package (it has Qwt only for Qt 5).
# Called by scripts/setup.sh after the Debian packages are installed.
#
# Leaves a Qt 6 Qwt where CMake's FindQwt looks (cmake/FindQwt.cmake):
#   1. a packaged one (libqwt-qt6-dev) if the system's apt sources have it;
#   2. otherwise Qwt built once from Debian unstable's source package `qwt`
#      as a static library into $FOG_QWT_QT6_PREFIX (default
#      /opt/fogbench-qwt-qt6 as root, ~/.cache/fogbench/qwt-qt6 otherwise).
#      The source is the orig tarball fetched by `apt-get source` through a
#      private apt configuration (its own sources.list with one deb-src line
#      for unstable, its own lists and cache in a scratch folder): the
#      system's apt sources are not touched. Only the library is built: no
#      designer plugin, examples, tests or OpenGL canvas.
# Idempotent: a finished prefix (its stamp file names this Qwt and this Qt)
# is left alone. Exits 0 with a message saying the build will use Qt 5 +
# Qwt 6.1 when Qwt for Qt 6 cannot be had; never leaves a half-built prefix.
set -euo pipefail

# All in one function, so that bash has read the whole script before it runs.
main() {

log() { echo "setup-qwt-qt6: $*"; }
fallback() {
  log "$*"
  log "no Qwt for Qt 6: the build falls back to Qt 5.15 + Qwt 6.1 (Debian 12's libqwt-qt5-dev)"
  exit 0
}

if [[ $(id -u) -eq 0 ]]; then
  default_prefix=/opt/fogbench-qwt-qt6
  sudo=()
else
  default_prefix="${HOME}/.cache/fogbench/qwt-qt6"
  sudo=(sudo)
fi
prefix="${FOG_QWT_QT6_PREFIX:-$default_prefix}"

qmake=$(command -v qmake6 || true)
[[ -n "$qmake" ]] || qmake=/usr/lib/qt6/bin/qmake
[[ -x "$qmake" ]] || fallback "qmake6 not found (package qmake6)"
qt_version=$("$qmake" -query QT_VERSION 2>/dev/null) || fallback "qmake6 does not run"

# 1. Already there: a packaged Qt 6 Qwt, or our prefix from an earlier run.
if dpkg-query -W -f='${Status}' libqwt-qt6-dev 2>/dev/null | grep -q 'install ok installed'; then
  log "Qwt for Qt 6 is installed (libqwt-qt6-dev)"
  exit 0
fi
stamp="$prefix/fogbench-qwt.txt"
if [[ -f "$stamp" && -f "$prefix/lib/libqwt.a" ]] && grep -qx "qt=$qt_version" "$stamp"; then
  log "Qwt for Qt 6 is in $prefix ($(grep '^qwt=' "$stamp"), static, built against Qt $qt_version)"
  exit 0
fi

# 2. Packaged by the system's own sources (Debian 13 and later).
if apt-cache show libqwt-qt6-dev >/dev/null 2>&1; then
  log "installing libqwt-qt6-dev from the system's apt sources"
  if DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends libqwt-qt6-dev; then
    exit 0
  fi
  log "installing libqwt-qt6-dev failed; building Qwt instead"
fi

# 3. Build from Debian unstable's source package.
for tool in make bzip2 tar; do
  command -v "$tool" >/dev/null 2>&1 || fallback "$tool not found"
done
scratch=$(mktemp -d /tmp/fogbench-qwt.XXXXXX)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch"/apt/{lists/partial,cache/archives/partial,sources.list.d,preferences.d} "$scratch/src"
mirror="${FOG_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
echo "deb-src [signed-by=$keyring] $mirror unstable main" > "$scratch/apt/sources.list"
apt_private=(
  -o "Dir::Etc::sourcelist=$scratch/apt/sources.list"
  -o "Dir::Etc::sourceparts=$scratch/apt/sources.list.d"
  -o "Dir::Etc::preferencesparts=$scratch/apt/preferences.d"
  -o "Dir::State::Lists=$scratch/apt/lists"
  -o "Dir::Cache=$scratch/apt/cache"
  -o "APT::Sandbox::User=root"
)
log "fetching the qwt source package from Debian unstable (private apt configuration in $scratch/apt)"
if ! apt-get "${apt_private[@]}" -qq update 2>"$scratch/update.err"; then
  # An archive key newer than this system's keyring: the tarball's hash is
  # still checked against the Sources index, which is then unauthenticated.
  log "signature check of unstable's index failed ($(tail -1 "$scratch/update.err")); retrying unauthenticated"
  echo "deb-src [trusted=yes] $mirror unstable main" > "$scratch/apt/sources.list"
  apt-get "${apt_private[@]}" -qq -o Acquire::AllowInsecureRepositories=true update \
    || fallback "cannot read Debian unstable's source index from $mirror"
fi
# The .dsc may not be served; the orig tarball is what is needed.
if ! (cd "$scratch/src" && apt-get "${apt_private[@]}" -qq --allow-unauthenticated source --download-only qwt \
        >"$scratch/source.log" 2>&1); then
  log "apt-get source qwt did not fetch every file (expected: the .dsc is not always served):"
  sed 's/^/    /' "$scratch/source.log"
fi
shopt -s nullglob
tarballs=("$scratch"/src/qwt_*.orig.tar.*)
shopt -u nullglob
[[ ${#tarballs[@]} -eq 1 ]] || fallback "apt-get source qwt fetched no orig tarball"
tarball="${tarballs[0]}"
qwt_version=$(basename "$tarball" | sed -E 's/^qwt_([0-9.]+)\.orig\..*/\1/')
case "$qwt_version" in
  6.[2-9]*|6.[1-9][0-9]*|[7-9].*) ;;
  *) fallback "Debian unstable has Qwt $qwt_version; Qt 6 needs Qwt >= 6.2" ;;
esac

log "building Qwt $qwt_version (static library only) with $qmake against Qt $qt_version into $prefix"
start=$SECONDS
mkdir -p "$scratch/build"
tar -xf "$tarball" -C "$scratch/build"
srcdir=$(find "$scratch/build" -mindepth 1 -maxdepth 1 -type d | head -1)
[[ -f "$srcdir/qwtconfig.pri" ]] || fallback "the tarball holds no qwtconfig.pri"
staging="$prefix.partial"
rm -rf "$staging"
{
  echo ""
  echo "# fogbench: static library only, installed into the prefix"
  echo "QWT_INSTALL_PREFIX = $staging"
  echo "QWT_INSTALL_DOCS = $staging/doc"
  echo "QWT_INSTALL_HEADERS = $staging/include"
  echo "QWT_INSTALL_LIBS = $staging/lib"
  echo "QWT_INSTALL_PLUGINS = $staging/plugins/designer"
  echo "QWT_INSTALL_FEATURES = $staging/features"
  echo "QWT_CONFIG -= QwtDll QwtDesigner QwtExamples QwtPlayground QwtTests QwtOpenGL QwtMathML"
} >> "$srcdir/qwtconfig.pri"
jobs="${FOG_QWT_JOBS:-$(nproc)}"
if ! (cd "$srcdir" && "$qmake" qwt.pro >"$scratch/build.log" 2>&1 \
        && make -j"$jobs" >>"$scratch/build.log" 2>&1 \
        && make install >>"$scratch/build.log" 2>&1); then
  tail -30 "$scratch/build.log" >&2
  rm -rf "$staging"
  fallback "building Qwt $qwt_version failed (log above)"
fi
[[ -f "$staging/lib/libqwt.a" && -f "$staging/include/qwt_global.h" ]] \
  || { rm -rf "$staging"; fallback "the Qwt build installed no libqwt.a"; }
rm -rf "$staging/doc" "$staging/plugins"
printf 'qwt=%s\nqt=%s\nsource=%s (Debian unstable, apt-get source qwt)\n' \
  "$qwt_version" "$qt_version" "$(basename "$tarball")" > "$staging/fogbench-qwt.txt"
rm -rf "$prefix"
mv "$staging" "$prefix"
log "Qwt $qwt_version for Qt $qt_version built in $((SECONDS - start)) s into $prefix"
}

main "$@"
