#!/bin/sh
# The ray budget: six glass slabs with MIRROR 0.9 TRANSMIT 0.9 and DEPTH 32
# spawn a reflected and a refracted ray at every hit that all hit again; the
# tree had 2^32 leaves and one pixel did not finish in 100 s. Now the
# coefficients are scaled to sum 1 with a located warning, the weight cut
# ends each branch, and at most 1024 secondary rays per sample are traced.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "ray_budget.sh: $*" >&2; exit 1; }
slabs() {   # slabs MIRROR TRANSMIT DIFFUSE
  printf 'EYE 0 0 0\nLOOKAT 0.3 1 0.2\nLIGHT 0 0 0.5\nDEPTH 32\n'
  printf 'ATTR GLASS COLOR 0.9 0.9 1 MIRROR %s TRANSMIT %s DIFFUSE %s IOR 1.5\n' "$1" "$2" "$3"
  for y in -8 -5 -2 1 4 7; do
    printf 'BLOCK C%s 40 1 40 TRANSLATE -20 %s -20 ATTR GLASS\nOBJECT C%s\n' "${y#-}" "$y" "${y#-}"
  done
}
get() { sed -n "s/^$1=//p" "$tmp/stats"; }
slabs 0.9 0.9 0 > "$tmp/issue.scene"
timeout 120 $MAPRT render "$tmp/issue.scene" -o "$tmp/a.png" --size 16x16 --threads 1 --stats > "$tmp/stats" 2> "$tmp/err" ||
  fail "the deck did not finish: $(cat "$tmp/err")"
grep -qx "maprt: $tmp/issue.scene:5:6: warning: ATTR GLASS: DIFFUSE 0 + MIRROR 0.9 + TRANSMIT 0.9 = 1.8 sends on more light than arrives; scaled by 0.5556 to DIFFUSE 0, MIRROR 0.5, TRANSMIT 0.5" "$tmp/err" ||
  fail "energy warning: $(cat "$tmp/err")"
# every ray hits again: with weights 0.5 the cut (1/512) ends each branch at
# depth 8, 2 + 4 + ... + 256 = 510 secondary rays a pixel, under the cap
sec=$(( $(get rays.reflected) + $(get rays.refracted) ))
[ "$sec" -gt $((256 * 400)) ] && [ "$sec" -le $((256 * 1024)) ] || fail "secondary rays $sec for 256 pixels"
# MIRROR 0.9 TRANSMIT 0.1 conserves energy and keeps many branches above the
# cut: the per-pixel cap stops them (rays.capped)
slabs 0.9 0.1 0 > "$tmp/cap.scene"
timeout 120 $MAPRT render "$tmp/cap.scene" -o "$tmp/b.png" --size 16x16 --threads 1 --stats > "$tmp/stats" 2> "$tmp/err" ||
  fail "the capped deck did not finish: $(cat "$tmp/err")"
[ -s "$tmp/err" ] && fail "a deck that conserves energy warned: $(cat "$tmp/err")"
sec=$(( $(get rays.reflected) + $(get rays.refracted) ))
[ "$sec" -le $((256 * 1024)) ] || fail "over the cap: $sec secondary rays for 256 pixels"
[ -n "$(get rays.capped)" ] && [ "$(get rays.capped)" -gt 0 ] || fail "the cap did not act: $(cat "$tmp/stats")"
# with --aa 2 the cap is per sample: 4 x 1024 a pixel
timeout 120 $MAPRT render "$tmp/cap.scene" -o "$tmp/b.png" --size 4x4 --aa 2 --threads 1 --stats > "$tmp/stats" 2>&1 ||
  fail "--aa 2 failed"
sec=$(( $(get rays.reflected) + $(get rays.refracted) ))
[ "$sec" -le $((16 * 4 * 1024)) ] || fail "over the cap with --aa 2: $sec"
exit 0
