#!/bin/sh
# make bench-peers times maprt against bench/peers/minimal.c, a hand-written
# f64 tracer of bench/peers/sphere.scene; the ratio compares like with like
# only while both draw the same picture. Both at 256x192 here (the rows
# just below the horizon included): every pixel byte equal. Exit 77
# (skipped) without a C compiler.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "minimal.sh: $*" >&2; exit 1; }
cc=${CC:-cc}
command -v "$cc" >/dev/null 2>&1 || { echo "skipped: needs a C compiler ($cc)"; exit 77; }
"$cc" -std=c99 -O2 -o "$tmp/minimal" bench/peers/minimal.c -lm || fail "bench/peers/minimal.c did not build"
"$tmp/minimal" "$tmp/min.ppm" 256 192 || fail "the minimal tracer failed"
$MAPRT render bench/peers/sphere.scene -o "$tmp/maprt.ppm" --size 256x192 --numeric f64 --threads 1 --quiet \
  || fail "maprt render failed"
out=$($MAPRT compare "$tmp/min.ppm" "$tmp/maprt.ppm" --threshold 0) || fail "maprt compare failed"
over=$(printf '%s\n' "$out" | sed -n 's/^pixels_over=//p')
[ "$over" = "0.000000" ] || fail "the pictures differ: pixels_over=$over at threshold 0"
echo "ok: minimal tracer and maprt f64 agree on every pixel byte at 256x192"
