#!/bin/sh
# maprt render: outputs, exit codes and exact diagnostics.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "render.sh: $*" >&2; exit 1; }

$MAPRT render --help | grep -q -- '--numeric MODE' || fail "--help lacks --numeric"
$MAPRT render scenes/fig1.scene -o "$tmp/a.png" --size 40x30 --threads 2 --aa 2 --stats > "$tmp/stats" \
  || fail "render failed"
[ -s "$tmp/a.png" ] || fail "no PNG written"
grep -qx 'rays.primary=4800' "$tmp/stats" || fail "rays.primary should be 40*30*4"
for k in rays.shadow rays.reflected rays.refracted pds.lookups fx.overflows time.render_s csg.pruned; do
  grep -q "^$k=" "$tmp/stats" || fail "--stats lacks $k"
done
for m in q16 q32 f32 f64; do
  $MAPRT render scenes/csg.scene -o "$tmp/$m.png" --size 16x16 --numeric $m || fail "mode $m"
done
ls "$tmp" | grep -q tmp- && fail "temporary file left behind"

$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --numeric q8 2> "$tmp/err"; [ $? -eq 2 ] || fail "bad mode should exit 2"
grep -q "'q8' is not q16, q32, f32 or f64" "$tmp/err" || fail "bad mode message"
$MAPRT render scenes/fig1.scene 2> /dev/null; [ $? -eq 2 ] || fail "no output should exit 2"
$MAPRT render -o "$tmp/x.png" 2> /dev/null; [ $? -eq 2 ] || fail "no scene should exit 2"
$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --aa 0 2> /dev/null; [ $? -eq 2 ] || fail "--aa 0 should exit 2"
$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --bogus 2> /dev/null; [ $? -eq 2 ] || fail "unknown option should exit 2"

$MAPRT render "$tmp/none.scene" -o "$tmp/x.png" 2> /dev/null; [ $? -eq 3 ] || fail "missing scene should exit 3"
printf 'EYE 0 0 0\nLOOKAT 1 0 0\nSPHERE S -1\n' > "$tmp/bad.scene"
$MAPRT render "$tmp/bad.scene" -o "$tmp/x.png" 2> "$tmp/err"; [ $? -eq 1 ] || fail "bad scene should exit 1"
grep -q "^maprt: $tmp/bad.scene:3:[0-9]*: error: " "$tmp/err" || fail "bad scene message: $(cat "$tmp/err")"
[ -e "$tmp/x.png" ] && fail "output written for a failed render"

$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --dl "$tmp/x.dl5080" 2> "$tmp/err"; [ $? -eq 3 ] || fail "--dl should exit 3"
grep -q "display-list output not available" "$tmp/err" || fail "--dl message"
exit 0
