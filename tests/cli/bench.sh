#!/bin/sh
# maprt bench: table, CSV and usage errors.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "bench.sh: $*" >&2; exit 1; }

$MAPRT bench --help | grep -q 'f64, which is the reference' || fail "--help"
$MAPRT bench scenes/fig1.scene --size 24x24 --modes q16,f64 --threads 1 --csv "$tmp/b.csv" > "$tmp/out" \
  || fail "bench failed"
[ "$(wc -l < "$tmp/b.csv")" -eq 3 ] || fail "CSV should hold a header and 2 rows"
head -1 "$tmp/b.csv" | grep -q '^scene,mode,threads,seconds' || fail "CSV header"
grep -q '^scenes/fig1.scene,f64,1,.*,inf,0.0000,0,0,0.0000,0$' "$tmp/b.csv" || fail "f64 row should match its reference"
# The System/370 HFP modes: a row each, no exceptions beyond significance on fig1.
$MAPRT bench scenes/fig1.scene --size 24x24 --modes hfp32,hfp64 --threads 1 --csv "$tmp/h.csv" > /dev/null \
  || fail "bench hfp failed"
grep -q '^scenes/fig1.scene,hfp32,1,.*,0,[0-9.]*,0$' "$tmp/h.csv" || fail "hfp32 row"
grep -q '^scenes/fig1.scene,hfp64,1,.*,0,[0-9.]*,0$' "$tmp/h.csv" || fail "hfp64 row"
$MAPRT bench scenes/fig1.scene --modes q16,x 2> /dev/null; [ $? -eq 2 ] || fail "bad mode should exit 2"
$MAPRT bench 2> /dev/null; [ $? -eq 2 ] || fail "no scene should exit 2"
exit 0
