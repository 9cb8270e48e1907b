#!/bin/sh
# Checks the Debian packages maprt builds and tests with. As root it installs the
# missing ones; otherwise it prints the exact apt-get line and fails.
PKGS="gcc make pkg-config libpng-dev zlib1g-dev libcmocka-dev gfortran libosmesa6-dev libegl-dev libgl-dev libgles-dev libgl1-mesa-dri libegl-mesa0 clang libclang-rt-14-dev libomp-dev gnuplot-nox povray"
command -v dpkg-query >/dev/null 2>&1 || { echo "deps: not a Debian system; install the equivalents of: $PKGS" >&2; exit 0; }
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
  echo "deps: installing$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends $missing >/dev/null || {
    echo "deps: apt-get failed; run: apt-get install -y$missing" >&2; exit 1; }
else
  echo "deps: missing packages; run as root:" >&2
  echo "  apt-get install -y$missing" >&2
  exit 1
fi
