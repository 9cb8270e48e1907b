#!/bin/sh
# maprt render --progress / --quiet: the progress lines, the closing summary,
# and a picture that does not depend on whether progress was measured.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "progress.sh: $*" >&2; exit 1; }

$MAPRT render scenes/fig1.scene --size 96x64 --aa 2 --threads 2 -o "$tmp/p.png" --progress 2> "$tmp/err" \
  || fail "--progress render failed"
grep -q '^render 100%  [0-9.:]* s* *elapsed  ETA 0 s  [0-9.]* [kM]*rays/s  (tiles 6/6)$' "$tmp/err" \
  || fail "no final progress line: $(cat "$tmp/err")"
# the closing line: what, time (wall and CPU), rays, rate, outputs
grep -q "^maprt: scenes/fig1.scene: 96x64, aa 2, q16: .* (CPU .*), [0-9.]* Mrays, [0-9.]* [kM]*rays/s; wrote $tmp/p.png\$" \
  "$tmp/err" || fail "no summary line: $(cat "$tmp/err")"
# the share never goes down and ends at 100
awk '/^render/ { p = $2 + 0; if (p < last) bad = 1; last = p } END { exit bad || last != 100 }' "$tmp/err" \
  || fail "progress not monotonic: $(cat "$tmp/err")"

$MAPRT render scenes/fig1.scene --size 96x64 --aa 2 --threads 2 -o "$tmp/q.png" --quiet 2> "$tmp/err" \
  || fail "--quiet render failed"
[ -s "$tmp/err" ] && fail "--quiet printed: $(cat "$tmp/err")"
# stderr is not a terminal here: quiet by default too
$MAPRT render scenes/fig1.scene --size 96x64 --aa 2 --threads 2 -o "$tmp/r.png" 2> "$tmp/err" || fail "render"
[ -s "$tmp/err" ] && fail "progress without a terminal: $(cat "$tmp/err")"
# measuring the tile costs draws pixels that the render then overwrites
$MAPRT compare "$tmp/p.png" "$tmp/q.png" | grep -qx 'psnr=inf' || fail "--progress changed the picture"
exit 0
