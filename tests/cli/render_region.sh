#!/bin/sh
# maprt render --region/--part and maprt merge: regions that do not follow
# the tile grid assemble into exactly the bytes of one whole render (PNG,
# DL5080 and, with --part-ids, the identity map), with the same counters
# (the scene's objects and instances once, not per part), for a fixed split
# and a random one; bad part sets, and parts of older formats, are refused
# with the reason.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "render_region.sh: $*" >&2; exit 1; }
# The pictures carry their date in their provenance: one date for all.
export SOURCE_DATE_EPOCH=536457600
deck=scenes/fig1.scene
$MAPRT render $deck -o "$tmp/one.png" --dl "$tmp/one.dl" --size 90x70 --aa 2 --numeric f64 \
  --stats > "$tmp/one.st" || fail "whole render failed"
# (the identity map costs PDS lookups of its own: a render of its own)
$MAPRT render $deck --ids "$tmp/one.ids" --size 90x70 --aa 2 --numeric f64 || fail "whole --ids render"
for r in 0,0,90,33 0,33,41,70 41,33,90,70; do
  $MAPRT render $deck --size 90x70 --aa 2 --numeric f64 --region $r --part "$tmp/p-$r" \
    || fail "region $r failed"
  $MAPRT render $deck --size 90x70 --aa 2 --numeric f64 --region $r --part "$tmp/i-$r" --part-ids \
    || fail "region $r with --part-ids failed"
done
$MAPRT merge "$tmp"/p-* --deck $deck -o "$tmp/m.png" --dl "$tmp/m.dl" --stats > "$tmp/m.st" || fail "merge failed"
cmp -s "$tmp/one.png" "$tmp/m.png" || fail "merged PNG differs from the whole render"
cmp -s "$tmp/one.dl" "$tmp/m.dl" || fail "merged DL5080 differs from the whole render"
$MAPRT merge "$tmp"/i-* --deck $deck -o "$tmp/mi.png" --ids "$tmp/mi.ids" || fail "merge --ids failed"
cmp -s "$tmp/one.ids" "$tmp/mi.ids" || fail "merged identity map differs from the whole render's"
cmp -s "$tmp/one.png" "$tmp/mi.png" || fail "merged PNG (parts with ids) differs"
# The map is not trivial: fig1's four primitives are all in view.
od -An -v -tu1 -j16 -w24 "$tmp/one.ids" | awk '!seen[$1]++ {n++} END {exit !(n >= 4)}' \
  || fail "the identity map shows fewer than four primitives"

# A random split (printed when it fails): a row cut, each side cut in two
# columns, q16 and --aa 1; every output the whole render writes, byte for byte.
split=$(awk -v s="$$" 'BEGIN {srand(s); y = 1 + int(rand() * 50); a = 1 + int(rand() * 70);
  b = 1 + int(rand() * 70); printf "0,0,%d,%d %d,0,71,%d 0,%d,%d,51 %d,%d,71,51", a, y, a, y, y, b, b, y}')
$MAPRT render $deck -o "$tmp/r1.png" --ids "$tmp/r1.ids" --size 71x51 || fail "whole 71x51 render"
for r in $split; do
  $MAPRT render $deck --size 71x51 --region $r --part "$tmp/r-$r" --part-ids || fail "split $split: $r"
done
$MAPRT merge "$tmp"/r-* --deck $deck -o "$tmp/r2.png" --ids "$tmp/r2.ids" || fail "split $split: merge"
cmp -s "$tmp/r1.ids" "$tmp/r2.ids" && cmp -s "$tmp/r1.png" "$tmp/r2.png" \
  || fail "split $split: merged outputs differ from the whole render's"
# The counters sum over the parts; the scene's counts are given once (here
# 5 objects, and of a grid of copies its instances, not times the parts).
samestats() {
  for k in rays.primary rays.shadow rays.reflected pds.lookups tests.prim fx.overflows objects \
    instances.moved instances.turned; do
    grep "^$k=" "$1" > "$tmp/a" && grep "^$k=" "$2" > "$tmp/b" || fail "$3: no $k"
    cmp -s "$tmp/a" "$tmp/b" || fail "$3: $k differs: $(cat "$tmp/a") vs $(cat "$tmp/b")"
  done
}
samestats "$tmp/one.st" "$tmp/m.st" fig1
GROW_TURN=1 sh bench/peers/grow.sh --deck 33 "$tmp/t33.scene" || fail "grow.sh --deck 33"
$MAPRT render "$tmp/t33.scene" -o "$tmp/t.png" --size 24x9 --numeric q16 --stats > "$tmp/t.st" || fail "grid"
for r in 0,0,24,5 0,5,24,9; do
  $MAPRT render "$tmp/t33.scene" --size 24x9 --numeric q16 --region $r --part "$tmp/t-$r" || fail "grid $r"
done
$MAPRT merge "$tmp"/t-* -o "$tmp/tm.png" --stats > "$tmp/tm.st" || fail "grid merge"
grep -qx 'instances.turned=1056' "$tmp/tm.st" || fail "grid merge: $(grep '^inst' "$tmp/tm.st" | tr '\n' ' ')"
samestats "$tmp/t.st" "$tmp/tm.st" "grid of turned copies"
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
grep -q 'offset 100: error: a region file has a 248-byte header' "$tmp/e" || fail "short: $(cat "$tmp/e")"
# Formats 1 (before the identity map) and 2 (before the scene's counts)
# are refused by name.
for f in 1 2; do
  { printf "MAPRTPT$f"; tail -c +9 "$tmp/all"; } > "$tmp/old"
  $MAPRT merge "$tmp/old" -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 1 ] || fail "format $f: exit"
  grep -q "offset 0: error: a region file of format $f (MAPRTPT$f, made by an older maprt); this maprt reads format 3 (MAPRTPT3): render the part again" "$tmp/e" \
    || fail "format $f: $(cat "$tmp/e")"
done
# Parts with and without the identity map do not mix; --ids needs it.
$MAPRT merge "$tmp/p-0,0,90,33" "$tmp/i-0,33,41,70" "$tmp/i-41,33,90,70" -o "$tmp/x.png" 2> "$tmp/e"
[ $? -eq 1 ] && grep -q 'part carries an identity map; the first part does not' "$tmp/e" \
  || fail "ids mix: $(cat "$tmp/e")"
$MAPRT merge "$tmp"/p-* --ids "$tmp/x.ids" 2> "$tmp/e"; [ $? -eq 1 ] || fail "--ids without: exit"
grep -q 'render them with --part-ids' "$tmp/e" || fail "--ids without: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --part-ids -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 2 ] || fail "--part-ids alone"
grep -q -- '--part-ids needs --part' "$tmp/e" || fail "--part-ids alone: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --region 0,0,91,10 --part "$tmp/x" 2> "$tmp/e"; [ $? -eq 2 ] || fail "outside"
grep -q 'not inside the 90x70 image' "$tmp/e" || fail "outside: $(cat "$tmp/e")"
$MAPRT render $deck --size 90x70 --region 5,5,5,9 --part "$tmp/x" 2> "$tmp/e"; [ $? -eq 2 ] || fail "empty"
$MAPRT render $deck --size 90x70 --region 0,0,9,9 -o "$tmp/x.png" 2> "$tmp/e"; [ $? -eq 2 ] || fail "-o"
grep -q "assemble the parts with 'maprt merge'" "$tmp/e" || fail "-o: $(cat "$tmp/e")"
[ ! -e "$tmp/x.png" ] && [ ! -e "$tmp/x" ] && [ ! -e "$tmp/x.ids" ] || fail "a refused command wrote a file"
exit 0
