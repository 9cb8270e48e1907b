#!/bin/sh
# The paper's claim on Figure 1 itself: scenes/fig1.scene (the object as one
# cylinder whose faces carry PDSs) against scenes/fig1-single.scene (the
# same object from single-attribute primitives joined by CSG), rendered at
# the same size on one thread in every numeric mode; best of three render
# times (wall, time.render_s) and the CPU seconds of that run (user + sys of
# the process, compile included). Also how close the two pictures are
# (maprt compare, per mode). Usage: sh bench/fig1.sh [MAPRT]  (env: SIZE=512x512,
# MODES="q16 q32 f32 f64")
bin=${1:-build/maprt}
size=${SIZE:-512x512}
modes=${MODES:-q16 q32 f32 f64}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "fig1.sh: $*" >&2; exit 1; }

# Primitive statements of a deck (no solid of either deck is used twice).
prims() {
  awk '{ w = toupper(substr($0, 1, 72)); sub(/^ +/, "", w); split(w, t, " ") }
       t[1] ~ /^(SPHERE|CYLINDER|CONE|BLOCK|HALFSPACE)$/ { n++ } END { print n }' "$1"
}

# best of three: "wall cpu" of the run with the smallest time.render_s
best() {
  b=""
  for r in 1 2 3; do
    /usr/bin/time -f "%U %S" -o "$tmp/cpu" "$bin" render "$1" -o "$tmp/$3.png" --size "$size" \
      --threads 1 --numeric "$2" --stats > "$tmp/stats" || exit 1
    s=$(sed -n 's/^time.render_s=//p' "$tmp/stats")
    c=$(awk '{ print $1 + $2 }' "$tmp/cpu")
    b=$(awk -v b="$b" -v s="$s" -v c="$c" 'BEGIN { split(b, x, " ");
      print (b == "" || s < x[1]) ? s " " c : b }')
  done
  echo "$b"
}

pm=$(prims scenes/fig1.scene); ps=$(prims scenes/fig1-single.scene)
echo "mode,primitives_multi,primitives_single,multi_s,multi_cpu_s,single_s,single_cpu_s,time_ratio,cpu_ratio,psnr_db,ssim,pixels_over_8"
for m in $modes; do
  a=$(best scenes/fig1.scene "$m" multi) && b=$(best scenes/fig1-single.scene "$m" single) ||
    fail "a render failed ($m)"
  "$bin" compare "$tmp/multi.png" "$tmp/single.png" > "$tmp/cmp" || fail "compare failed ($m)"
  awk -v m="$m" -v pm="$pm" -v ps="$ps" -v a="$a" -v b="$b" -F= '
    { v[$1] = $2 }
    END { split(a, x, " "); split(b, y, " ");
      printf "%s,%d,%d,%s,%.2f,%s,%.2f,%.2f,%.2f,%s,%s,%s\n", m, pm, ps, x[1], x[2], y[1], y[2],
        y[1] / x[1], y[2] / x[2], v["psnr"], v["ssim"], v["pixels_over"] }' "$tmp/cmp"
done
