#!/bin/sh
# maprt render: the output format follows the name (.png .ppm .pam, '-' with
# --format), anything else is refused before the work, and every picture
# carries its provenance (PNG tEXt, Netpbm comments).
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "render_outputs.sh: $*" >&2; exit 1; }
r() { $MAPRT render scenes/csg.scene --size 16x12 "$@"; }

r -o "$tmp/a.png" && r -o "$tmp/a.ppm" && r -o "$tmp/a.pam" || fail "render to png/ppm/pam failed"
head -c 8 "$tmp/a.png" | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a' || fail "a.png is not a PNG"
[ "$(head -c 2 "$tmp/a.ppm")" = P6 ] || fail "a.ppm is not a P6 PPM"
[ "$(head -c 2 "$tmp/a.pam")" = P7 ] || fail "a.pam is not a P7 PAM"
grep -a -q '^TUPLTYPE RGB$' "$tmp/a.pam" && grep -a -q '^WIDTH 16$' "$tmp/a.pam" || fail "PAM header"
# the same pixels in all three: the rasters are the last 16*12*3 bytes of
# the Netpbm files, and compare's PNM reader agrees with its PNG reader
[ "$(tail -c 576 "$tmp/a.ppm" | od -An -tx1)" = "$(tail -c 576 "$tmp/a.pam" | od -An -tx1)" ] \
  || fail "PPM and PAM rasters differ"
$MAPRT compare "$tmp/a.png" "$tmp/a.ppm" | grep -qx 'psnr=inf' || fail "PPM differs from PNG"

# standard output: needs --format, refuses a terminal and --stats
r -o - --format ppm > "$tmp/b.ppm" || fail "-o - --format ppm failed"
[ "$(tail -c 576 "$tmp/a.ppm" | od -An -tx1)" = "$(tail -c 576 "$tmp/b.ppm" | od -An -tx1)" ] \
  || fail "stdout PPM differs from the file"
r -o - --format PNG | head -c 4 | od -An -c | grep -q 'P   N   G' || fail "--format is case-insensitive"
r -o - > "$tmp/out" 2> "$tmp/err"; [ $? -eq 2 ] || fail "-o - without --format should exit 2"
grep -q "standard output needs --format png, ppm or pam" "$tmp/err" || fail "message: $(cat "$tmp/err")"
[ -e ./- ] && fail "a file named '-' was created"
r -o - --format png --stats > /dev/null 2>&1; [ $? -eq 2 ] || fail "-o - with --stats should exit 2"

# any other name is refused before the work, and writes nothing
for n in x.jpg x.tiff x noext.PNG.bak; do
  r -o "$tmp/$n" 2> "$tmp/err"; [ $? -eq 2 ] || fail "-o $n should exit 2"
  grep -q "must end in .png, .ppm or .pam" "$tmp/err" || fail "message for $n: $(cat "$tmp/err")"
  [ -e "$tmp/$n" ] && fail "$n was written"
done
r -o "$tmp/x.PNG" || fail "the ending is case-insensitive"
r -o "$tmp/c.png" --format ppm 2> "$tmp/err"; [ $? -eq 2 ] || fail "contradicting --format should exit 2"

# outputs that are always PNG (dl2png, compare's pictures) must be named so
r --dl "$tmp/a.dl5080" || fail "render --dl"
$MAPRT dl2png "$tmp/a.dl5080" "$tmp/v.jpg" 2> "$tmp/err"; [ $? -eq 2 ] || fail "dl2png to .jpg should exit 2"
grep -q "this output is a PNG, so its name must end in .png" "$tmp/err" && [ ! -e "$tmp/v.jpg" ] || fail "dl2png .jpg"
$MAPRT compare "$tmp/a.png" "$tmp/a.png" --diff "$tmp/d.tif" 2> /dev/null; [ $? -eq 2 ] || fail "--diff .tif should exit 2"

# provenance: the version, deck and its SHA-256, mode, size, aa, date
SOURCE_DATE_EPOCH=0 $MAPRT render scenes/csg.scene --size 16x12 --aa 2 --numeric F64 -o "$tmp/p.png" \
  || fail "provenance render"
sum=$(sha256sum scenes/csg.scene | cut -d' ' -f1)
for kv in "Software.maprt $($MAPRT --version | sed 's/^maprt //')" "Creation Time.1970-01-01T00:00:00Z" \
          "maprt:deck.scenes/csg.scene" "maprt:deck-sha256.$sum" "maprt:numeric.f64" \
          "maprt:size.16x12" "maprt:aa.2"; do
  k=${kv%%.*}; v=${kv#*.}
  # tEXt chunk data is KEY NUL VALUE
  LC_ALL=C tr '\000' '=' < "$tmp/p.png" | LC_ALL=C grep -a -q -F "tEXt$k=$v" || fail "PNG lacks tEXt $k=$v"
done
grep -a -q "^# maprt:deck-sha256: $sum\$" "$tmp/a.ppm" || fail "PPM lacks the provenance comments"
exit 0
