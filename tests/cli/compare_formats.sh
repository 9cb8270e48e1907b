#!/bin/sh
# maprt compare reads JPEG and TIFF written by an independent encoder
# (ImageMagick), and warns with exit status 4 when a pair does not match.
set -u
. tests/need.sh
need_cmd convert imagemagick
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "compare_formats.sh: $*" >&2; exit 1; }
get() { sed -n "s/^$1=//p" "$tmp/out"; }

$MAPRT render scenes/fig1.scene --size 96x72 -o "$tmp/a.png" || fail "render"
convert "$tmp/a.png" -quality 100 "$tmp/a.jpg" && convert "$tmp/a.png" "$tmp/a.tif" \
  && convert "$tmp/a.png" -depth 16 "$tmp/a16.tif" && convert "$tmp/a.png" -compress lzw "$tmp/lzw.tif" \
  && convert "$tmp/a.png" -colorspace gray "$tmp/grey.tif" && convert "$tmp/grey.tif" "$tmp/grey.png" \
  || fail "convert failed"
$MAPRT compare "$tmp/a.png" "$tmp/a.jpg" > "$tmp/out" 2> "$tmp/err"; rc=$?
if grep -q "built without JPEG support" "$tmp/err"; then
  echo "skipped: maprt built without libjpeg (apt-get install -y libjpeg62-turbo-dev)"; exit 77
fi
[ $rc -eq 0 ] || fail "JPEG compare exited $rc: $(cat "$tmp/err")"
awk -v p="$(get psnr)" 'BEGIN { exit !(p > 40) }' || fail "JPEG q100 psnr $(get psnr) <= 40"
for f in a.tif a16.tif lzw.tif; do
  $MAPRT compare "$tmp/a.png" "$tmp/$f" > "$tmp/out" 2> "$tmp/err" || fail "TIFF $f: $(cat "$tmp/err")"
  [ "$(get psnr)" = inf ] || fail "lossless TIFF $f differs: psnr $(get psnr)"
done
$MAPRT compare "$tmp/grey.png" "$tmp/grey.tif" --grey > "$tmp/out" || fail "grey TIFF"
[ "$(get psnr)" = inf ] || fail "grey TIFF differs: psnr $(get psnr)"
# truncated files: located errors, exit 1
head -c 200 "$tmp/a.jpg" > "$tmp/cut.jpg"; head -c 100 "$tmp/a.tif" > "$tmp/cut.tif"
for f in cut.jpg cut.tif; do
  $MAPRT compare "$tmp/a.png" "$tmp/$f" > /dev/null 2> "$tmp/err"; [ $? -eq 1 ] || fail "$f should exit 1"
  grep -q "^maprt: $tmp/$f: error: \(JPEG\|TIFF\): " "$tmp/err" || fail "$f message: $(cat "$tmp/err")"
done

# mismatch: a different scene, registered, is measured and flagged (exit 4)
$MAPRT render scenes/fig1.scene --size 144x108 --numeric f64 -o "$tmp/big.png" || fail "render big"
$MAPRT render scenes/csg.scene --size 96x72 -o "$tmp/csg.png" || fail "render csg"
$MAPRT compare "$tmp/big.png" "$tmp/a.jpg" --register > "$tmp/out" 2> "$tmp/err" || fail "same scene flagged: $(cat "$tmp/err")"
$MAPRT compare "$tmp/big.png" "$tmp/csg.png" --register > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 4 ] || fail "different scene exited $rc, not 4"
[ -n "$(get register_score)" ] || fail "figures not printed on a mismatch"
grep -q "warning: .* do not look like the same picture (register_score 0\.[0-9]* < 0\.78)" "$tmp/err" \
  || fail "mismatch warning: $(cat "$tmp/err")"
$MAPRT compare --help | grep -q '4 measured' || fail "--help does not document exit 4"
exit 0
