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
for k in rays.shadow rays.reflected rays.refracted pds.lookups fx.overflows time.render_s csg.pruned skipped.uv \
  skipped.shadow objects instances.moved instances.turned; do
  grep -q "^$k=" "$tmp/stats" || fail "--stats lacks $k"
done
# The instances the compile took, in a coarse mode and a fine one: fig1's
# five objects are no copies; of the growth bench's 33 x 33 parts (and
# floor) every part but the first is a translated copy, and turned
# (GROW_TURN=1) 1,056 meet scene_inst_find's criteria; at 10 x 10 they
# are too few for the compile to take (CSCENE_INST_MIN).
sh bench/peers/grow.sh --deck 33 "$tmp/g33.scene" && GROW_TURN=1 sh bench/peers/grow.sh --deck 33 "$tmp/t33.scene" \
  && sh bench/peers/grow.sh --deck 10 "$tmp/g10.scene" || fail "grow.sh --deck"
for want in "fig1 scenes/fig1.scene 5 0 0" "g33 $tmp/g33.scene 1090 1088 0" "t33 $tmp/t33.scene 1090 0 1056" \
  "g10 $tmp/g10.scene 101 0 0"; do
  set -- $want
  for m in q16 f64; do
    $MAPRT render "$2" -o "$tmp/i.png" --size 8x6 --threads 1 --numeric $m --stats > "$tmp/st" || fail "$1 $m: render"
    got=$(grep -E '^(objects|instances\.(moved|turned))=' "$tmp/st" | cut -d= -f2 | tr '\n' ' ')
    [ "$got" = "$3 $4 $5 " ] || fail "$1 $m: objects, instances.moved, instances.turned are $got, not $3 $4 $5"
  done
done
for m in q16 q32 f32 f64; do
  $MAPRT render scenes/csg.scene -o "$tmp/$m.png" --size 16x16 --numeric $m || fail "mode $m"
done
ls "$tmp" | grep -q tmp- && fail "temporary file left behind"

$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --numeric q8 2> "$tmp/err"; [ $? -eq 2 ] || fail "bad mode should exit 2"
grep -q "'q8' is not q16, q32, f32, f64, hfp32 or hfp64" "$tmp/err" || fail "bad mode message"
$MAPRT render scenes/fig1.scene 2> /dev/null; [ $? -eq 2 ] || fail "no output should exit 2"
$MAPRT render -o "$tmp/x.png" 2> /dev/null; [ $? -eq 2 ] || fail "no scene should exit 2"
$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --aa 0 2> /dev/null; [ $? -eq 2 ] || fail "--aa 0 should exit 2"
$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --bogus 2> /dev/null; [ $? -eq 2 ] || fail "unknown option should exit 2"

$MAPRT render "$tmp/none.scene" -o "$tmp/x.png" 2> /dev/null; [ $? -eq 1 ] || fail "missing scene should exit 1"
$MAPRT render 'NONE SCENE A' --disk "A=$tmp" -o "$tmp/x.png" 2> "$tmp/err"; [ $? -eq 1 ] || fail "missing fileid should exit 1"
grep -qx "maprt: NONE SCENE A1: error: file not found (RC 28)" "$tmp/err" || fail "RC 28 message: $(cat "$tmp/err")"
printf 'EYE 0 0 0\nLOOKAT 1 0 0\nSPHERE S -1\n' > "$tmp/bad.scene"
$MAPRT render "$tmp/bad.scene" -o "$tmp/x.png" 2> "$tmp/err"; [ $? -eq 1 ] || fail "bad scene should exit 1"
grep -q "^maprt: $tmp/bad.scene:3:[0-9]*: error: " "$tmp/err" || fail "bad scene message: $(cat "$tmp/err")"
[ -e "$tmp/x.png" ] && fail "output written for a failed render"

# Through the CMS shim: fileids in and out, and the display list with a wireframe.
$MAPRT render 'FIG1 SCENE A' --disk A=scenes --disk "B=$tmp" -o 'FIG1 PNG B' --dl 'FIG1 DL5080 B' \
  --wireframe --size 64x48 --stats > "$tmp/stats" || fail "render by fileid failed"
[ -s "$tmp/fig1.png" ] && [ -s "$tmp/fig1.dl5080" ] || fail "fileid outputs missing: $(ls "$tmp")"
grep -q '^dl.colours=' "$tmp/stats" && grep -q '^dl.bytes=' "$tmp/stats" || fail "--stats lacks dl keys"
$MAPRT dl validate "$tmp/fig1.dl5080" > /dev/null || fail "display list does not validate"
$MAPRT dl2png "$tmp/fig1.dl5080" "$tmp/back.png" || fail "dl2png of the render failed"
$MAPRT render scenes/fig1.scene -o "$tmp/x.png" --dither 2> "$tmp/err"; [ $? -eq 2 ] || fail "--dither without --dl should exit 2"
$MAPRT render scenes/fig1.scene --dl "$tmp/x.dl5080" --dac 6 2> "$tmp/err"; [ $? -eq 2 ] || fail "--dac 6 should exit 2"
$MAPRT render scenes/fig1.scene --dl "$tmp/x.dl5080" --size 5000x10 2> "$tmp/err"; [ $? -eq 2 ] || fail "oversize --dl should exit 2"
grep -q "at most 4096x4096" "$tmp/err" || fail "oversize message"
# An output name that is a FIFO or a directory is refused, not replaced.
mkfifo "$tmp/fifo.png" && mkdir "$tmp/dir.png"
$MAPRT render scenes/csg.scene -o "$tmp/fifo.png" --size 8x8 2> "$tmp/err"; [ $? -eq 3 ] || fail "FIFO output should exit 3"
grep -q "not a regular file" "$tmp/err" && [ -p "$tmp/fifo.png" ] || fail "FIFO replaced: $(cat "$tmp/err")"
$MAPRT render scenes/csg.scene -o "$tmp/dir.png" --size 8x8 2> /dev/null; [ $? -eq 3 ] && [ -d "$tmp/dir.png" ] || fail "directory output should exit 3"
# --ids: the identity map, 16 + 24 bytes a pixel (docs/idmap.md), alone or
# with a PNG; a precision event is reported on stderr without --stats; a
# primitive beyond the mode's limits is refused before rendering.
$MAPRT render scenes/csg.scene --ids "$tmp/c.ids" --size 10x7 2> "$tmp/err" || fail "--ids failed"
[ "$(wc -c < "$tmp/c.ids")" -eq $((16 + 24 * 70)) ] || fail "--ids size"
[ "$(head -c 8 "$tmp/c.ids")" = MAPRTID1 ] || fail "--ids magic"
[ -s "$tmp/err" ] && fail "a clean render printed: $(cat "$tmp/err")"
$MAPRT render tests/decks/deep-floor.scene -o "$tmp/d.png" --size 32x32 2> "$tmp/err" || fail "deep floor failed"
[ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -q "^maprt: tests/decks/deep-floor.scene: warning: q16: 0 fixed-point overflows, [1-9][0-9]* primary rays beyond" "$tmp/err" \
  || fail "range warning: $(cat "$tmp/err")"
$MAPRT render tests/decks/deep-floor.scene -o "$tmp/d.png" --size 32x32 --numeric q32 2> "$tmp/err" || fail "deep floor q32 failed"
[ -s "$tmp/err" ] && fail "q32 deep floor printed: $(cat "$tmp/err")"
$MAPRT render tests/decks/thin-disc.scene -o "$tmp/t.png" --size 16x16 2> "$tmp/err"; [ $? -eq 1 ] || fail "thin disc should exit 1 in q16"
grep -q "^maprt: tests/decks/thin-disc.scene:9:1: error: primitive 'COIN': aspect ratio 5e+04 is beyond the q16 limit of 10000 (docs/numerics.md); use --numeric q32 or f64$" "$tmp/err" \
  || fail "thin disc message: $(cat "$tmp/err")"
[ -e "$tmp/t.png" ] && fail "output written for a refused scene"
$MAPRT render tests/decks/thin-disc.scene -o "$tmp/t.png" --size 16x16 --numeric f64 || fail "thin disc f64 failed"
ls "$tmp" | grep -q tmp- && fail "temporary file left behind"
exit 0
