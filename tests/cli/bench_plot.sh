#!/bin/sh
# maprt bench --plot: a PNG chart through gnuplot (skipped where gnuplot is absent).
set -u
. tests/need.sh
need_cmd gnuplot gnuplot-nox
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "bench_plot.sh: $*" >&2; exit 1; }
$MAPRT bench scenes/csg.scene --size 16x16 --modes q16,f64 --threads 1 --plot "$tmp/b.png" > /dev/null \
  || fail "bench --plot failed"
head -c 8 "$tmp/b.png" | od -An -c | grep -q 'P   N   G' || fail "--plot did not write a PNG"
exit 0
