#!/bin/sh
# make bench-peers: maprt (q16 and f64, one thread) against POV-Ray 3.7 on
# the scenes of bench/peers (each .pov the same picture as its .scene,
# checked here: share of pixels differing by more than 8/255), and f64
# against bench/peers/minimal.c (a hand-written tracer of sphere.scene;
# maprt both as PNG and, like the minimal tracer, as PPM).
# Each command runs N times (PEERS_RUNS, default 5), the commands
# alternating so load changes hit all alike; the medians of whole-process
# CPU seconds (user + sys) and wall seconds are printed, then the ratios
# (maprt time / peer time: below 1 means maprt is faster), last the
# ratios of the CPU minima (the runs a shared machine disturbed least).
# Then the whole process on 1 and 2 threads (fig1 1024x1024, q16), beside
# what the host's two cores give two processes that share nothing (two
# minimal tracers at once against one), and its peak RSS. Exit status 1 when the minimal tracer's picture is not
# maprt's (every figure is printed all the same), 3 when a command fails.
# Usage: sh bench/peers/run.sh [MAPRT [MINIMAL [CPUTIME]]]
bin=${1:-build/maprt}
minimal=${2:-build/bench/minimal}
cputime=${3:-$(dirname "$minimal")/cputime}
runs=${PEERS_RUNS:-5}
status=0
dir=$(dirname "$0")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/maprt-peers-XXXXXX") || exit 3
trap 'rm -rf "$tmp"' EXIT INT TERM
command -v povray >/dev/null 2>&1 || { echo "bench-peers: povray (Debian povray) is not installed" >&2; exit 3; }

. "$dir/lib.sh"
need_timer
# maprt runs its x86-64-v3 tracer where it can (render --isa): the minimal
# tracer then runs its x86-64-v3 build beside it (MINIMAL-v3, the Makefile)
isa=$("$bin" render bench/peers/sphere.scene -o "$tmp/isa.ppm" --size 8x6 --numeric f64 --stats 2>/dev/null |
      sed -n 's/^isa=//p')
if [ "$isa" = x86-64-v3 ]; then
  [ -x "$minimal-v3" ] || { echo "bench-peers: maprt runs x86-64-v3 code and $minimal-v3 is not built" >&2; exit 3; }
  minimal=$minimal-v3
fi
pov() { povray "+I$1" "+L$dir" "+O$2" "+W$3" "+H$4" +WT1 -D "File_Gamma=1.0" Display=off "$5"; }

echo "scene,size,pixels_over_8,q16_cpu_s,f64_cpu_s,pov_cpu_s,q16_wall_s,f64_wall_s,pov_wall_s,q16/pov_cpu,f64/pov_cpu,q16/pov_wall,f64/pov_wall,q16/pov_cpu_min,f64/pov_cpu_min"
for spec in sphere:bench/peers/sphere.scene:1024:768 csg1:bench/peers/csg1.scene:1024:768 \
            csg81:bench/peers/csg81.scene:1024:768 slab8:bench/slab-8.scene:640:480; do
  name=${spec%%:*}; rest=${spec#*:}; scene=${rest%%:*}; rest=${rest#*:}; w=${rest%%:*}; h=${rest#*:}
  # the picture check: POV-Ray's PPM against maprt's f64 PNG
  pov "$dir/$name.pov" "$tmp/$name.ppm" "$w" "$h" +FP >/dev/null 2>&1 || { echo "bench-peers: povray failed on $name" >&2; exit 3; }
  "$bin" render "$scene" -o "$tmp/$name.png" --size "${w}x$h" --numeric f64 --threads 1 || exit 3
  over=$("$bin" compare "$tmp/$name.ppm" "$tmp/$name.png" | sed -n 's/^pixels_over=//p')
  i=0
  while [ "$i" -lt "$runs" ]; do
    run "$name.q16" "$bin" render "$scene" -o "$tmp/o.png" --size "${w}x$h" --numeric q16 --threads 1
    run "$name.f64" "$bin" render "$scene" -o "$tmp/o.png" --size "${w}x$h" --numeric f64 --threads 1
    run "$name.pov" povray "+I$dir/$name.pov" "+L$dir" "+O$tmp/p.png" "+W$w" "+H$h" +WT1 -D "File_Gamma=1.0" Display=off
    i=$((i + 1))
  done
  qc=$(med "$name.q16" 1); fc=$(med "$name.f64" 1); pc=$(med "$name.pov" 1)
  qw=$(med "$name.q16" 2); fw=$(med "$name.f64" 2); pw=$(med "$name.pov" 2)
  ql=$(least "$name.q16" 1); fl=$(least "$name.f64" 1); pl=$(least "$name.pov" 1)
  echo "$name,${w}x$h,$over,$qc,$fc,$pc,$qw,$fw,$pw,$(ratio "$qc" "$pc"),$(ratio "$fc" "$pc"),$(ratio "$qw" "$pw"),$(ratio "$fw" "$pw"),$(ratio "$ql" "$pl"),$(ratio "$fl" "$pl")"
done

# at 2048x1536: at 1024x768 the minimal tracer runs for a few
# hundredths of a second, within the start-up's noise
echo
echo "sphere.scene at 2048x1536 against the minimal tracer (bench/peers/minimal.c as $minimal; maprt's tracer: ${isa:-unknown}):"
"$minimal" "$tmp/min.ppm" 2048 1536 || exit 3
"$bin" render bench/peers/sphere.scene -o "$tmp/sphere2.png" --size 2048x1536 --numeric f64 --threads 1 || exit 3
# the ratio below compares like with like only if the pictures are the same
same=$("$bin" compare "$tmp/min.ppm" "$tmp/sphere2.png" --threshold 0 | sed -n 's/^pixels_over=//p')
echo "pixels differing (minimal vs maprt f64): $same"
[ "$same" = "0.000000" ] || { echo "bench-peers: the minimal tracer's picture is not maprt's: the ratios below compare unlike work" >&2; status=1; }
i=0
while [ "$i" -lt "$runs" ]; do
  run min "$minimal" "$tmp/min.ppm" 2048 1536
  run sf64 "$bin" render bench/peers/sphere.scene -o "$tmp/o.png" --size 2048x1536 --numeric f64 --threads 1
  run sf64p "$bin" render bench/peers/sphere.scene -o "$tmp/o.ppm" --size 2048x1536 --numeric f64 --threads 1
  run sq16 "$bin" render bench/peers/sphere.scene -o "$tmp/o.png" --size 2048x1536 --numeric q16 --threads 1
  i=$((i + 1))
done
echo "minimal cpu_s=$(med min 1) wall_s=$(med min 2); f64 cpu_s=$(med sf64 1) wall_s=$(med sf64 2); f64 writing PPM cpu_s=$(med sf64p 1); q16 cpu_s=$(med sq16 1)"
echo "f64/minimal cpu=$(ratio "$(med sf64 1)" "$(med min 1)") wall=$(ratio "$(med sf64 2)" "$(med min 2)") cpu_min=$(ratio "$(least sf64 1)" "$(least min 1)")"
# the minimal tracer writes an uncompressed PPM: the same output, like for like
echo "f64 (PPM)/minimal cpu=$(ratio "$(med sf64p 1)" "$(med min 1)") wall=$(ratio "$(med sf64p 2)" "$(med min 2)") cpu_min=$(ratio "$(least sf64p 1)" "$(least min 1)")"
echo "q16/f64 (sphere) cpu=$(ratio "$(med sq16 1)" "$(med sf64 1)")"

echo
echo "whole process, scenes/fig1.scene 1024x1024 q16, 1 and 2 threads:"
i=0
while [ "$i" -lt "$runs" ]; do
  run t1 "$bin" render scenes/fig1.scene -o "$tmp/o.png" --size 1024x1024 --threads 1
  run t2 "$bin" render scenes/fig1.scene -o "$tmp/o.png" --size 1024x1024 --threads 2
  run f1 "$bin" render scenes/fig1.scene -o "$tmp/o.png" --size 1024x1024 --threads 1 --numeric f64
  # what the host gives two processes that share nothing: two minimal
  # tracers at once against one (no path reaches the shell's text)
  run h1 "$minimal" "$tmp/h1.ppm" 2048 1536
  run h2 sh -c '"$1" "$2" 2048 1536 & "$1" "$3" 2048 1536; wait' sh "$minimal" "$tmp/h1.ppm" "$tmp/h2.ppm"
  i=$((i + 1))
done
echo "1 thread wall_s=$(med t1 2) cpu_s=$(med t1 1); 2 threads wall_s=$(med t2 2) cpu_s=$(med t2 1); speed-up $(ratio "$(med t1 2)" "$(med t2 2)") (of the wall minima $(ratio "$(least t1 2)" "$(least t2 2)"))"
echo "the host's two cores: two minimal tracers at once do $(ratio "$(awk -v a="$(med h1 2)" 'BEGIN { print 2 * a }')" "$(med h2 2)")x the work of one in the same wall time (of the wall minima $(ratio "$(awk -v a="$(least h1 2)" 'BEGIN { print 2 * a }')" "$(least h2 2)"))"
echo "q16/f64 (fig1) cpu=$(ratio "$(med t1 1)" "$(med f1 1)")"
/usr/bin/time -f "%M" -o "$tmp/rss" "$bin" render scenes/fig1.scene -o "$tmp/o.png" --size 1024x1024 >/dev/null 2>&1
echo "peak RSS fig1 1024x1024: $(awk '{ printf "%.1f MiB", $1 / 1024 }' "$tmp/rss")"
exit "$status"
