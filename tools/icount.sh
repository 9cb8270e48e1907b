#!/bin/sh
# usage: sh tools/icount.sh MAPRT [MODES]
# Instruction counts of whole renders (valgrind --tool=callgrind, one
# thread, PPM output so no PNG encoding is counted; OMP_WAIT_POLICY=passive
# keeps libgomp's idle threads from spinning, so two runs of one binary
# agree to 0.001 %). Repeatable whatever else the machine runs: the measure
# for changes inside the tracer (docs/performance.md). ISA=baseline counts
# the baseline build of the tracer (render --isa; default auto).
bin=${1:?usage: icount.sh MAPRT [MODES]}
modes=${2:-q16 f64}
command -v valgrind >/dev/null 2>&1 || { echo "icount: valgrind is not installed" >&2; exit 3; }
for spec in bench/peers/sphere.scene:256x192 bench/peers/csg1.scene:256x192 \
            bench/peers/csg81.scene:256x192 bench/slab-8.scene:160x120 scenes/fig1.scene:128x128; do
  deck=${spec%%:*}; size=${spec#*:}
  for m in $modes; do
    n=$(OMP_WAIT_POLICY=passive valgrind --tool=callgrind --callgrind-out-file=/dev/null \
          "$bin" render "$deck" -o - --format ppm --size "$size" --numeric "$m" --threads 1 --isa "${ISA:-auto}" --quiet 2>&1 >/dev/null |
        sed -n 's/.*Collected : *//p')
    echo "$(basename "$deck" .scene) $size $m $n"
  done
done
