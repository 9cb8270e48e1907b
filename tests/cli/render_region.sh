#!/bin/sh
# maprt render --region/--part and maprt merge: regions that do not follow
# the tile grid assemble into exactly the bytes of one whole render (PNG and
# DL5080), with the same counters; bad part sets are refused with the reason.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "render_region.sh: $*" >&2; exit 1; }
# The pictures carry their date in their provenance: one date for all.
export SOURCE_DATE_EPOCH=536457600
deck=scenes/fig1.scene
$MAPRT render $deck -o "$tmp/one.png" --dl "$tmp/one.dl" --size 90x70 --aa 2 --numeric f64 \
  --stats > "$tmp/one.st" || fail "whole render failed"
for r in 0,0,90,33 0,33,41,70 41,33,90,70; do
  $MAPRT render $deck --size 90x70 --aa 2 --numeric f64 --region $r --part "$tmp/p-$r" \
    || fail "region $r failed"
done
$MAPRT merge "$tmp"/p-* --deck $deck -o "$tmp/m.png" --dl "$tmp/m.dl" --stats > "$tmp/m.st" || fail "merge failed"
cmp -s "$tmp/one.png" "$tmp/m.png" || fail "merged PNG differs from the whole render"
cmp -s "$tmp/one.dl" "$tmp/m.dl" || fail "merged DL5080 differs from the whole render"
for k in rays.primary rays.shadow rays.reflected pds.lookups tests.prim fx.overflows; do
  grep "^$k=" "$tmp/one.st" > "$tmp/a" && grep "^$k=" "$tmp/m.st" > "$tmp/b" || fail "no $k"
  cmp -s "$tmp/a" "$tmp/b" || fail "$k differs: $(cat "$tmp/a") vs $(cat "$tmp/b")"
done
# A whole-image part merges to the same bytes too.
$MAPRT render $deck --size 90x70 --aa 2 --numeric f64 --part "$tmp/all" || fail "--part alone"
$MAPRT merge "$tmp/all" --deck $deck -o "$tmp/m2.png" && cmp -s "$tmp/one.png" "$tmp/m2.png" || fail "whole part"

# Refusals, each with its reason.
$MAPRT merge "$tmp/p-0,0,90,33" -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 1 ] || fail "gap: exit"
grep -q 'leave pixel 0,33' "$tmp/e" || fail "gap: $(cat "$tmp/e")"
$MAPRT merge "$tmp/p-0,0,90,33" "$tmp/all" -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 1 ] || fail "overlap"
grep -q 'is in two regions' "$tmp/e" || fail "overlap: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --numeric q16 --region 0,33,90,70 --part "$tmp/q16" || fail "q16"
$MAPRT merge "$tmp/p-0,0,90,33" "$tmp/q16" -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 1 ] || fail "mix"
grep -q 'first part is 90x70 f64 with --aa 2' "$tmp/e" || fail "mix: $(cat "$tmp/e")"
head -c 100 "$tmp/all" > "$tmp/short"
$MAPRT merge "$tmp/short" -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 1 ] || fail "short"
grep -q 'offset 100: error: a region file has a 220-byte header' "$tmp/e" || fail "short: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --region 0,0,91,10 --part "$tmp/x" 2> "$tmp/e"; [ $? -eq 2 ] || fail "outside"
grep -q 'not inside the 90x70 image' "$tmp/e" || fail "outside: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --region 5,5,5,9 --part "$tmp/x" 2> "$tmp/e"; [ $? -eq 2 ] || fail "empty"
$MAPRT render $deck --size 90x70 --region 0,0,9,9 -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 2 ] || fail "-o"
grep -q "assemble the parts with 'maprt merge'" "$tmp/e" || fail "-o: $(cat "$tmp/e")"
[ ! -e "$tmp/x.png" ] && [ ! -e "$tmp/x" ] || fail "a refused command wrote a file"
exit 0
