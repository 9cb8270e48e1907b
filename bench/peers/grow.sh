#!/bin/sh
# make bench-grow: cost against the number of objects, maprt (q16, f64)
# beside POV-Ray 3.7. An n x n grid of the CSG part of csg81.scene (a box
# meets a sphere, minus three cylinders), scaled so the grid always covers
# the same 27 x 27 square on the same mirror floor, seen by the same camera
# and lights: n = 1, 3, 10, 32, 100 (1 to 10,000 objects, 5 to 50,000
# primitives). One thread, whole process, medians of N alternated runs
# (GROW_RUNS, default 3); printed: CPU seconds (medians) and each tool's
# cost over its own cost at one object: the median of the ratios of runs
# paired in time (each round runs the one-object scene just before the
# n x n one, so that a shared machine's load, which drifts over the
# minutes a table takes, weighs on both alike), the ratio of the minima
# (the three columns after the pixels), the runs such a machine
# disturbed least, and (the last two) in how many rounds each mode grew
# less than POV-Ray in the same round, k/N: were the tools alike, each
# round would go either way as a coin does, so k near N/2 says the
# growths are level, and k or N - k at most 1 of 11 rounds is a
# difference a coin gives by chance about once in 85 (a sign test). The
# scenes are written here, both from the one list of placements. GROW_TURN=1 turns
# each object about x, then y, then z by angles drawn from a fixed
# pseudo-random sequence (awk's srand(1)): no two objects then share a
# linear part, and the twins of the grid (model/prim_twin.h) give nothing,
# though each is still a turned copy of the first (an instance,
# docs/numerics.md). GROW_VARY=1 scales object k by 1 + 10^-3 k / n^2
# besides: no object is then a copy of another, and each is traced as its
# own.
# Usage: sh bench/peers/grow.sh [MAPRT [CPUTIME]]
# sh bench/peers/grow.sh --deck N FILE writes the deck of the n x n grid
# to FILE and does nothing else (for timing one size alone, tools/ab.sh);
# --pov N FILE writes POV-Ray's scene of it likewise.
dir=$(dirname "$0")

# place N: the grid's scale, turns (degrees about x, y, z) and
# translations, one object a line
place() {
  awk -v n="$1" -v turn="${GROW_TURN:-0}" -v vary="${GROW_VARY:-0}" 'BEGIN {
    s = 9 / n; step = 27 / n; srand(1)
    for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
      ax = ay = az = 0
      if (turn == 1) { ax = 360 * rand(); ay = 360 * rand(); az = 360 * rand() }
      sk = vary == 1 ? s * (1 + 1e-3 * (n * i + j) / (n * n)) : s
      printf (vary == 1 ? "%.9f" : "%.6f") " %.4f %.4f %.4f %.6f %.6f %.6f\n", sk, ax, ay, az,
             -13.5 + step * (i + 0.5), -13.5 + step * (j + 0.5), s - 1
    }
  }'
}
# emit TURNED PLAIN PLACEMENTS: each placement through the printf format
# TURNED (scale, the three turns, translation) with GROW_TURN=1, else
# through PLAIN (scale, translation)
emit() {
  awk -v turn="${GROW_TURN:-0}" -v tf="$1" -v pf="$2" '{
    if (turn == 1)
      printf tf, $1, $2, $3, $4, $5, $6, $7
    else
      printf pf, $1, $5, $6, $7
  }' "$3"
}
# deck PLACEMENTS: the maprt deck of those placements on standard output
# (a card holds 72 columns: the turns go on a continuation card)
deck() {
  sed -n '/^EYE/,/^HALFSPACE/p' "$dir/csg81.scene"
  emit 'OBJECT PART SCALE %s ROTATE X %s ROTATE Y %s -\n  ROTATE Z %s TRANSLATE %s %s %s\n' \
       'OBJECT PART SCALE %s TRANSLATE %s %s %s\n' "$1"
  echo "OBJECT GROUND"
}
# pov PLACEMENTS: the POV-Ray scene of those placements on standard output
# (it includes csg.inc: render it with +L bench/peers)
pov() {
  sed -n '1,/^#include/p' "$dir/csg81.pov"
  emit 'object { Part scale %s rotate <%s, 0, 0> rotate <0, %s, 0> rotate <0, 0, %s> translate <%s, %s, %s> }\n' \
       'object { Part scale %s translate <%s, %s, %s> }\n' "$1"
  echo "object { Floor }"
}

if [ "${1:-}" = --deck ] || [ "${1:-}" = --pov ]; then
  what=${1#--}
  n=${2:?usage: grow.sh --deck|--pov N FILE}; out=${3:?usage: grow.sh --deck|--pov N FILE}
  case $n in ''|*[!0-9]*|0) echo "bench-grow: N must be a positive count" >&2; exit 2 ;; esac
  for read in "$dir/csg81.scene" "$dir/csg81.pov" "$dir/csg.inc"; do
    [ -e "$out" ] && [ "$out" -ef "$read" ] && { echo "bench-grow: $out is a file read" >&2; exit 2; }
  done
  p=$(mktemp "${TMPDIR:-/tmp}/maprt-grow-XXXXXX") || exit 3
  o=$(mktemp "$(dirname "$out")/.maprt-grow-XXXXXX") || { rm -f "$p"; exit 3; }
  place "$n" > "$p" && "$what" "$p" > "$o" && mv -f "$o" "$out"; status=$?
  rm -f "$p" "$o"
  exit "$status"
fi

bin=${1:-build/maprt}
cputime=${2:-build/bench/cputime}
runs=${GROW_RUNS:-3}
size=${GROW_SIZE:-512x384}
w=${size%x*}; h=${size#*x}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/maprt-grow-XXXXXX") || exit 3
trap 'rm -rf "$tmp"' EXIT INT TERM
command -v povray >/dev/null 2>&1 || { echo "bench-grow: povray (Debian povray) is not installed" >&2; exit 3; }
. "$dir/lib.sh"
need_timer

# scenes N: $tmp/gN.scene and $tmp/gN.pov
scenes() {
  n=$1
  place "$n" > "$tmp/place"
  deck "$tmp/place" > "$tmp/g$n.scene"
  pov "$tmp/place" > "$tmp/g$n.pov"
}

# paired T N: the median over the rounds of T's CPU at n = N over its CPU
# at one object in the same round (1.00 for N = 1)
paired() {
  [ "$2" = 1 ] && { echo 1.00; return; }
  paste -d ' ' "$tmp/$1$2.t" "$tmp/${1}1_$2.t" | awk '$5 > 0 { print $1 / $5 }' | sort -n |
    awk '{ v[NR] = $1 } END { printf "%.2f\n", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# below T N: in how many rounds T's growth at n = N (its CPU at N over
# its CPU at one object, as paired takes it) was below POV-Ray's in the
# same round, as k/rounds ("-" for N = 1)
below() {
  [ "$2" = 1 ] && { echo -; return; }
  paste -d ' ' "$tmp/$1$2.t" "$tmp/${1}1_$2.t" "$tmp/p$2.t" "$tmp/p1_$2.t" |
    awk '$5 > 0 && $13 > 0 { n++; k += $1 / $5 < $9 / $13 } END { printf "%d/%d\n", k, n }'
}

# least1 T N: T's least CPU at one object, of the n = 1 runs and those
# paired with n = N
least1() {
  cat "$tmp/${1}1.t" $( [ "$2" = 1 ] || echo "$tmp/${1}1_$2.t") | sort -n | awk 'NR == 1 { printf "%.3f\n", $1 }'
}

echo "objects,q16_cpu_s,f64_cpu_s,pov_cpu_s,q16_growth,f64_growth,pov_growth,pixels_over_8,q16_growth_min,f64_growth_min,pov_growth_min,q16_rounds_below_pov,f64_rounds_below_pov"
for n in 1 3 10 32 100; do
  scenes "$n"
  povray "+I$tmp/g$n.pov" "+L$dir" "+O$tmp/g.ppm" "+W$w" "+H$h" +WT1 +FP -D "File_Gamma=1.0" Display=off >/dev/null 2>&1 \
    || { echo "bench-grow: povray failed on $n x $n" >&2; exit 3; }
  "$bin" render "$tmp/g$n.scene" -o "$tmp/g.png" --size "$size" --numeric f64 --threads 1 --quiet || exit 3
  over=$("$bin" compare "$tmp/g.ppm" "$tmp/g.png" | sed -n 's/^pixels_over=//p')
  i=0
  while [ "$i" -lt "$runs" ]; do
    for t in q f p; do
      # the pair: one object (from the second size on), then n x n
      for k in $( [ "$n" = 1 ] && echo "$n" || echo "1 $n"); do
        label=$t$k; [ "$k" != "$n" ] && label=${t}1_$n
        case $t in
          q) run "$label" "$bin" render "$tmp/g$k.scene" -o "$tmp/o.png" --size "$size" --numeric q16 --threads 1 --quiet ;;
          f) run "$label" "$bin" render "$tmp/g$k.scene" -o "$tmp/o.png" --size "$size" --numeric f64 --threads 1 --quiet ;;
          p) run "$label" povray "+I$tmp/g$k.pov" "+L$dir" "+O$tmp/p.png" "+W$w" "+H$h" +WT1 -D "File_Gamma=1.0" Display=off ;;
        esac
      done
    done
    i=$((i + 1))
  done
  row="$((n * n))"
  for t in q f p; do row="$row,$(med "$t$n" 1)"; done
  for t in q f p; do row="$row,$(paired "$t" "$n")"; done
  row="$row,$over"
  for t in q f p; do row="$row,$(ratio "$(least "$t$n" 1)" "$(least1 "$t" "$n")")"; done
  for t in q f; do row="$row,$(below "$t" "$n")"; done
  echo "$row"
done
