#!/bin/sh
# maprt compare on pictures written here with awk: a 96x96 colour "render"
# (PPM) and a grey "scan" of it (PGM) at scale 1.5, placed at (20,12) on a
# paper-toned page, faded. Registration must find the placement, write the
# pictures, and an identical pair must score perfectly.
set -u
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
fail() { echo "compare_register: $*" >&2; exit 1; }

# colour(x, y) of the scene in render pixels, shared by both pictures
scene='function col(x, y) {
  r = 40 + x; g = 50 + y / 2; b = 90
  dx = x - 35; dy = y - 38
  if (dx * dx + dy * dy < 400) { r = 200; g = 180; b = 60 }
  if (dx * dx + dy * dy < 100 && !(dx > 3 && dy > -4 && dy < 4)) { r = 30; g = 30; b = 160 }
  if (x > 62 && x < 74 && y > 15 && y < 80) { r = 230; g = 40; b = 40 }
  if (x > 62 && x < 88 && y > 15 && y < 25) { r = 230; g = 40; b = 40 }
  if (y > 70 && y < 86 && x > 10 && x < 50 && (int(x / 5) % 2) == 0) { r = 240; g = 240; b = 240 }
}'
awk "$scene"'BEGIN { print "P3\n# test render\n96 96\n255"
  for (y = 0; y < 96; y++) for (x = 0; x < 96; x++) { col(x + 0.5, y + 0.5); printf "%d %d %d\n", r, g, b } }' > "$t/render.ppm"
awk "$scene"'BEGIN { print "P2\n190 180\n255"
  for (y = 0; y < 180; y++) for (x = 0; x < 190; x++) {
    s = 0
    for (j = 0; j < 2; j++) for (i = 0; i < 2; i++) {
      xt = (x + 0.25 + 0.5 * i - 20) / 1.5; yt = (y + 0.25 + 0.5 * j - 12) / 1.5
      if (xt >= 0 && yt >= 0 && xt < 96 && yt < 96) { col(xt, yt); s += 235 - 0.7 * (255 - (0.299 * r + 0.587 * g + 0.114 * b)) }
      else s += 235
    }
    print int(s / 4 + 0.5) } }' > "$t/scan.pgm"

out=$("$MAPRT" compare "$t/scan.pgm" "$t/render.ppm" --register --grey --descreen 1 \
      --diff "$t/diff.png" --side-by-side "$t/sbs.png") || fail "registered compare failed"
printf '%s\n' "$out"
get() { printf '%s\n' "$out" | sed -n "s/^$1=//p"; }
for k in width height channels pixels overlap mse psnr ssim threshold pixels_over scale dx dy angle register_score; do
  [ -n "$(get $k)" ] || fail "no $k= line"
done
[ "$(get width)" = 190 ] && [ "$(get height)" = 180 ] && [ "$(get channels)" = luma ] || fail "wrong frame"
awk -v s="$(get scale)" -v x="$(get dx)" -v y="$(get dy)" -v a="$(get angle)" -v q="$(get ssim)" 'BEGIN {
  ok = (s / 1.5 - 1 < 0.01 && 1 - s / 1.5 < 0.01 && x - 20 < 1 && 20 - x < 1 && y - 12 < 1 && 12 - y < 1 &&
        a < 0.3 && a > -0.3 && q > 0.9); exit !ok }' || fail "registration off"
for f in diff sbs; do
  [ "$(head -c 4 "$t/$f.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "$f.png is not a PNG"
done

# the example of docs/compare.md: a crop moves the origin of dx, dy
out=$("$MAPRT" compare "$t/scan.pgm" "$t/render.ppm" --register --grey --crop 10,5,175,170 --descreen 1 \
      --levels) || fail "cropped compare failed"
printf '%s\n' "$out"
awk -v s="$(get scale)" -v x="$(get dx)" -v y="$(get dy)" 'BEGIN {
  ok = (s / 1.5 - 1 < 0.01 && 1 - s / 1.5 < 0.01 && x - 10 < 1 && 10 - x < 1 && y - 7 < 1 && 7 - y < 1); exit !ok }' ||
  fail "cropped registration off"
[ -n "$(get gain)" ] && [ -n "$(get offset)" ] || fail "no gain/offset with --levels"

out=$("$MAPRT" compare "$t/sbs.png" "$t/sbs.png") || fail "PNG compare failed"
[ "$(get psnr)" = inf ] && [ "$(get width)" = $((3 * 190 + 16)) ] || fail "PNG pair: $out"

out=$("$MAPRT" compare "$t/render.ppm" "$t/render.ppm") || fail "identical compare failed"
[ "$(get psnr)" = inf ] && [ "$(get ssim)" = 1.000000 ] && [ "$(get pixels_over)" = 0.000000 ] &&
  [ "$(get channels)" = rgb ] && [ "$(get overlap)" = 1.000000 ] || fail "identical pair not perfect: $out"

# The registration search is bounded by its cost cap: two 32x32 pictures
# over scale 0.01..100 and 45 degrees (about 10^12 pixel pairs, past 600 s
# before the cap) are refused at once, before any search.
printf 'P5 32 32 255\n' > "$t/small.pgm"
i=0; while [ $i -lt 1024 ]; do printf "\\$(printf '%03o' $(( (i * 7 + i / 32 * 13) % 256 )))"; i=$((i + 1)); done >> "$t/small.pgm"
start=$(date +%s)
timeout 60 "$MAPRT" compare "$t/small.pgm" "$t/small.pgm" --register --scale-range 0.01,100 --max-angle 45 \
  > /dev/null 2> "$t/err"; rc=$?
[ "$rc" -eq 1 ] || fail "over-cap registration: exit $rc: $(cat "$t/err")"
grep -q "would compare more than 4294967296 pixel pairs (32x32 reference, 32x32 test); narrow --scale-range" "$t/err" ||
  fail "cost cap message: $(cat "$t/err")"
[ $(( $(date +%s) - start )) -lt 20 ] || fail "the refusal took more than 20 s"
exit 0
