#!/bin/sh
# make bench: time against error for every scene in scenes/ and bench/ in all
# numeric modes (f64 and, when built, the REAL(16) oracle are the references), then the CSG-width figure: render time
# and primitive tests per ray of a slab minus N cylinders, N = 8 .. 256, and
# one multi-attribute primitive against single-attribute ones (attrmap.sh).
# Results go to out/. Timings depend on machine load.
bin=${1:-build/maprt}
size=${BENCH_SIZE:-320x240}
threads=${BENCH_THREADS:-1}
mkdir -p out
sh bench/slab.sh
plot=""
command -v gnuplot >/dev/null 2>&1 && plot="--plot out/bench.png"
oracle=""
[ -x "$(dirname "$bin")/oracle/ids_oracle" ] && oracle="--oracle $(dirname "$bin")/oracle/ids_oracle"
"$bin" bench scenes/*.scene bench/*.scene --size "$size" --threads "$threads" \
  --runs "${BENCH_RUNS:-3}" $oracle --csv out/bench.csv $plot || exit 1
echo
echo "slab minus N cylinders, q16, $size, $threads thread(s):"
echo "n,render_s,rays,prim_tests,prim_tests_per_ray" > out/slab.csv
for n in 8 16 32 64 128 256; do
  "$bin" render "bench/slab-$n.scene" -o "out/slab-$n.png" --size "$size" --threads "$threads" \
    --stats > out/slab-$n.stats || exit 1
  awk -F= -v n="$n" '
    /^rays\./ { rays += $2 } /^tests.prim=/ { tp = $2 } /^time.render_s=/ { ts = $2 }
    END { printf "%d,%s,%d,%d,%.2f\n", n, ts, rays, tp, tp / rays }' out/slab-$n.stats >> out/slab.csv
done
cat out/slab.csv
echo
echo "one multi-attribute primitive vs. single-attribute primitives (bench/attrmap.sh):"
sh bench/attrmap.sh "$bin" | tee out/attrmap.csv
echo
echo "Figure 1 itself, multi- vs. single-attribute (bench/fig1.sh):"
sh bench/fig1.sh "$bin" | tee out/fig1.csv
