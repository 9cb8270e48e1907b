#!/bin/sh
# The paper's efficiency claim, measured: one multi-attribute primitive
# against the same look built from single-attribute primitives. A 4 x 4
# panel shows an n x n checker of two attributes, either as one block whose
# front face carries a TILING PDS, or as n*n blocks of one attribute each
# joined by union (one OBJECT each). Both are rendered at the same size in
# q16 and f64 on one thread; the best of three render times is kept.
# Usage: sh bench/attrmap.sh [MAPRT]   (env: SIZE=512x512, NS="4 8 16 32")
bin=${1:-build/maprt}
size=${SIZE:-512x512}
ns=${NS:-4 8 16 32}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

header() {
  cat <<'DECK'
EYE 0 -10 2.1
LOOKAT 0 0 2.1
UP 0 0 1
FOV 28
AMBIENT 0.2 0.2 0.2
LIGHT 3 -8 9 INTENSITY 0.8
ATTR RED COLOR 0.8 0.2 0.15 SPECULAR 0.3
ATTR CREAM COLOR 0.9 0.88 0.78 SPECULAR 0.3
ATTR FLOOR COLOR 0.45 0.45 0.48
HALFSPACE GROUND ATTR FLOOR
OBJECT GROUND
DECK
}

# best of three: the smallest time.render_s
best() {
  t=""
  for r in 1 2 3; do
    "$bin" render "$1" -o "$tmp/out.png" --size "$size" --threads 1 --numeric "$2" --stats \
      > "$tmp/stats" || exit 1
    s=$(sed -n 's/^time.render_s=//p' "$tmp/stats")
    t=$(awk -v a="$t" -v b="$s" 'BEGIN { print (a == "" || b < a) ? b : a }')
  done
  echo "$t"
}
fail() { echo "attrmap.sh: $*" >&2; exit 1; }

echo "n,primitives_multi,primitives_single,q16_multi_s,q16_single_s,q16_ratio,f64_multi_s,f64_single_s,f64_ratio"
for n in $ns; do
  { header
    awk -v n="$n" 'BEGIN { printf "PDS CHECK TILING SQUARE %.9f CYCLE 1 1 0\nTILES RED CREAM\nEND\n", 1 / n
      print "BLOCK PANEL 4 0.2 4 ATTR RED TRANSLATE -2 0 0.1"
      print "FACE PANEL YMIN CHECK"
      print "OBJECT PANEL" }'
  } > "$tmp/multi.scene"
  { header
    awk -v n="$n" 'BEGIN { w = 4 / n
      for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
        printf "BLOCK T%d_%d %.9f 0.2 %.9f ATTR %s -\n  TRANSLATE %.9f 0 %.9f\n", i, j, w, w,
          (i + j) % 2 ? "CREAM" : "RED", -2 + i * w, 0.1 + j * w
        printf "OBJECT T%d_%d\n", i, j } }'
  } > "$tmp/single.scene"
  qm=$(best "$tmp/multi.scene" q16) && qs=$(best "$tmp/single.scene" q16) &&
  fm=$(best "$tmp/multi.scene" f64) && fs=$(best "$tmp/single.scene" f64) || fail "a render failed (n=$n)"
  awk -v n="$n" -v qm="$qm" -v qs="$qs" -v fm="$fm" -v fs="$fs" 'BEGIN {
    printf "%d,%d,%d,%s,%s,%.1f,%s,%s,%.1f\n", n, 2, n * n + 1, qm, qs, qs / qm, fm, fs, fs / fm }'
done
