#!/bin/sh
# The shipped scenes: render --list names them, and `maprt render fig1`
# finds fig1.scene from any directory (MAPRT_SCENES first, then the
# installed share directory, then the source tree).
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
case $MAPRT in /*) ;; *) MAPRT=$PWD/$MAPRT ;; esac
fail() { echo "shipped.sh: $*" >&2; exit 1; }
src=$PWD

$MAPRT render --list > "$tmp/list" || fail "--list failed"
for f in scenes/*.scene; do
  n=$(basename "$f" .scene)
  grep -q "^  $n " "$tmp/list" || fail "--list lacks $n"
done
grep -q '^  fig1  *Figure 1 of the 1987 paper\.$' "$tmp/list" || fail "fig1's title: $(grep fig1 "$tmp/list")"

(cd "$tmp" && env -u MAPRT_SCENES $MAPRT render fig1 -o fig1.png --size 32x24 --stats > stats) || fail "render fig1 from $tmp"
[ -s "$tmp/fig1.png" ] || fail "no fig1.png"
# the same deck as scenes/fig1.scene: its checksum in the provenance
sum=$(sha256sum "$src/scenes/fig1.scene" | cut -d' ' -f1)
LC_ALL=C tr '\000' '=' < "$tmp/fig1.png" | LC_ALL=C grep -a -q "maprt:deck-sha256=$sum" || fail "fig1 is not scenes/fig1.scene"
# MAPRT_SCENES comes first
mkdir "$tmp/mine" && cp "$src/scenes/csg.scene" "$tmp/mine/fig1.scene"
(cd "$tmp" && MAPRT_SCENES="$tmp/mine" $MAPRT render fig1 -o mine.png --size 32x24) || fail "MAPRT_SCENES"
sum=$(sha256sum "$src/scenes/csg.scene" | cut -d' ' -f1)
LC_ALL=C tr '\000' '=' < "$tmp/mine.png" | LC_ALL=C grep -a -q "maprt:deck-sha256=$sum" || fail "MAPRT_SCENES not first"
# a host file of that name wins
cp "$src/scenes/csg.scene" "$tmp/fig1"
(cd "$tmp" && $MAPRT render fig1 -o host.ppm --size 32x24) || fail "host file fig1"
grep -a -qx "# maprt:deck: fig1" "$tmp/host.ppm" && grep -a -qx "# maprt:deck-sha256: $sum" "$tmp/host.ppm" \
  || fail "host file fig1 not used"
# every command that reads a deck takes the name (bench here)
(cd "$tmp" && env -u MAPRT_SCENES $MAPRT bench csg --size 16x16 --modes q16,f64 --threads 1 > bench.out) \
  || fail "bench csg from $tmp"
grep -q '^S1  *csg  *f64 ' "$tmp/bench.out" || fail "bench csg: $(cat "$tmp/bench.out")"
# an unknown name is still an error naming it
(cd "$tmp" && $MAPRT render nosuchscene -o x.png) 2> "$tmp/err"; [ $? -eq 1 ] || fail "unknown scene should exit 1"
exit 0
