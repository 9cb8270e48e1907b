#!/bin/sh
# maprt-mpi under mpirun (Open MPI): three ranks (oversubscribed on a small
# machine) write exactly the bytes of a single-process render, PNG, DL5080
# and identity map, with the counters summed over ranks (the scene's
# objects and instances given once) and each rank's share; bench writes
# the CSV rows of one process (timings and the rank column aside) with the
# cells spread over the ranks; a failed cell, a bad deck or a rank killed
# mid-render or mid-sweep fails the job with a message and leaves no
# output. maprt, which links no MPI, refuses to be one of several ranks.
# Exit 77 (skipped) when there is no maprt-mpi (no Open MPI at build time)
# or no mpirun.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "mpi.sh: $*" >&2; exit 1; }
command -v mpirun >/dev/null 2>&1 || { echo "skipped: needs mpirun (apt-get install -y openmpi-bin)"; exit 77; }
mpibin=$(dirname "$MAPRT")/maprt-mpi
[ -x "$mpibin" ] || { echo "skipped: needs maprt-mpi, built where Open MPI is (apt-get install -y libopenmpi-dev, then rebuild)"; exit 77; }
ldd "$MAPRT" 2>/dev/null | grep -q libmpi && fail "maprt links libmpi; only maprt-mpi should"
# Open MPI refuses root unless told; leak checkers do not know its caches.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=detect_leaks=0
# The pictures carry their date in their provenance: one date for all.
export SOURCE_DATE_EPOCH=536457600
mpi() { mpirun --oversubscribe -n 3 "$@"; }
mpi $MAPRT render scenes/fig1.scene -o "$tmp/plain.png" --size 16x16 2> "$tmp/e" && fail "maprt ran as 3 ranks"
grep -q "built without MPI; run maprt-mpi under mpirun" "$tmp/e" || fail "plain maprt under mpirun: $(head -3 "$tmp/e")"
[ ! -e "$tmp/plain.png" ] || fail "plain maprt under mpirun wrote its output"
deck=scenes/fig1.scene
for m in q16 f64; do
  $MAPRT render $deck -o "$tmp/one-$m.png" --dl "$tmp/one-$m.dl" --size 120x90 --aa 2 --numeric $m \
    --threads 2 --stats > "$tmp/one-$m.st" || fail "single render $m"
  mpi $mpibin render $deck -o "$tmp/mpi-$m.png" --dl "$tmp/mpi-$m.dl" --size 120x90 --aa 2 \
    --numeric $m --threads 1 --stats > "$tmp/mpi-$m.st" || fail "mpirun render $m"
  cmp -s "$tmp/one-$m.png" "$tmp/mpi-$m.png" || fail "$m: PNG differs from the single-process render"
  cmp -s "$tmp/one-$m.dl" "$tmp/mpi-$m.dl" || fail "$m: DL5080 differs from the single-process render"
  grep -v '^time\.' "$tmp/one-$m.st" > "$tmp/a"
  grep -v '^time\.\|^mpi\.' "$tmp/mpi-$m.st" > "$tmp/b"
  cmp -s "$tmp/a" "$tmp/b" || fail "$m: counters differ: $(diff "$tmp/a" "$tmp/b" | tr '\n' ' ')"
  grep -qx 'mpi.ranks=3' "$tmp/mpi-$m.st" || fail "no mpi.ranks=3"
  bands=$(sed -n 's/^mpi\.rank[0-9]*\.bands=//p' "$tmp/mpi-$m.st" | awk '{s+=$1} END {print s}')
  [ "$bands" = 3 ] || fail "$m: ranks rendered $bands bands of 3"
done
# The identity map travels with the bands: the same bytes, the same counters.
$MAPRT render $deck --ids "$tmp/one.ids" -o "$tmp/one-i.png" --size 120x90 --aa 2 --numeric f64 \
  --threads 2 --stats > "$tmp/one-i.st" || fail "single render --ids"
mpi $mpibin render $deck --ids "$tmp/mpi.ids" -o "$tmp/mpi-i.png" --size 120x90 --aa 2 --numeric f64 \
  --threads 1 --stats > "$tmp/mpi-i.st" || fail "mpirun render --ids"
cmp -s "$tmp/one.ids" "$tmp/mpi.ids" || fail "--ids: identity map differs from the single-process render"
cmp -s "$tmp/one-i.png" "$tmp/mpi-i.png" || fail "--ids: PNG differs from the single-process render"
[ "$(wc -c < "$tmp/mpi.ids")" = $((16 + 24 * 120 * 90)) ] || fail "--ids: wrong size"
grep -v '^time\.' "$tmp/one-i.st" > "$tmp/a"
grep -v '^time\.\|^mpi\.' "$tmp/mpi-i.st" > "$tmp/b"
cmp -s "$tmp/a" "$tmp/b" || fail "--ids: counters differ: $(diff "$tmp/a" "$tmp/b" | tr '\n' ' ')"
# A grid of turned copies: the scene's counts (objects, instances) once,
# not times the ranks.
GROW_TURN=1 sh bench/peers/grow.sh --deck 33 "$tmp/t33.scene" || fail "grow.sh --deck 33"
$MAPRT render "$tmp/t33.scene" -o "$tmp/one-t.png" --size 48x70 --numeric q16 --stats > "$tmp/one-t.st" \
  || fail "single render of the grid"
mpi $mpibin render "$tmp/t33.scene" -o "$tmp/mpi-t.png" --size 48x70 --numeric q16 --threads 1 --stats \
  > "$tmp/mpi-t.st" || fail "mpirun render of the grid"
grep -E '^(objects|instances\.)' "$tmp/one-t.st" > "$tmp/a"
grep -E '^(objects|instances\.)' "$tmp/mpi-t.st" > "$tmp/b"
grep -qx 'instances.turned=1056' "$tmp/a" && cmp -s "$tmp/a" "$tmp/b" \
  || fail "grid: the scene's counts differ: $(cat "$tmp/a" "$tmp/b" | tr '\n' ' ')"

# bench: the rows of one process, in its order, but for the timings
# (seconds_median, rays_per_s) and the rank that ran each row.
set -- scenes/fig1.scene scenes/csg.scene scenes/coincident.scene --size 32x24 \
  --modes q16,q32,f64,hfp32 --runs 2 --threads 1
$MAPRT bench "$@" --csv "$tmp/b1.csv" > "$tmp/b1.out" || fail "single bench"
mpi $mpibin bench "$@" --csv "$tmp/b3.csv" > "$tmp/b3.out" || fail "mpirun bench"
untimed() { awk -F, 'BEGIN {OFS = ","} {$6 = ""; $8 = ""; $NF = ""; print}' "$1"; }
untimed "$tmp/b1.csv" > "$tmp/a"
untimed "$tmp/b3.csv" > "$tmp/b"
[ "$(wc -l < "$tmp/a")" = 13 ] || fail "bench: $(wc -l < "$tmp/a") CSV lines, not a header and 12 rows"
cmp -s "$tmp/a" "$tmp/b" || fail "bench: CSV rows differ: $(diff "$tmp/a" "$tmp/b" | tr '\n' ' ')"
head -1 "$tmp/b3.csv" | grep -q ',rank$' || fail "bench: no rank column"
[ "$(sed 1d "$tmp/b1.csv" | awk -F, '$NF != 0' | wc -l)" = 0 ] || fail "bench: one process is rank 0"
sed 1d "$tmp/b3.csv" | awk -F, '$NF !~ /^[012]$/ {bad++} !seen[$NF]++ {n++}
  END {exit !(!bad && n >= 2)}' || fail "bench: rank column $(sed 1d "$tmp/b3.csv" | awk -F, '{printf "%s ", $NF}')"
awk '/^S/ {$5 = ""; $6 = ""} {print}' "$tmp/b1.out" > "$tmp/a"
awk '/^S/ {$5 = ""; $6 = ""} {print}' "$tmp/b3.out" > "$tmp/b"
cmp -s "$tmp/a" "$tmp/b" || fail "bench: the table differs: $(diff "$tmp/a" "$tmp/b" | tr '\n' ' ')"
# The oracle's columns too, where the oracle is built.
oracle=$(dirname "$MAPRT")/oracle/ids_oracle
if [ -x "$oracle" ]; then
  set -- scenes/coincident.scene scenes/csg.scene --size 32x32 --modes q16,f64,hfp64 --runs 1 \
    --threads 1 --oracle "$oracle"
  $MAPRT bench "$@" --csv "$tmp/o1.csv" > /dev/null || fail "single bench --oracle"
  mpi $mpibin bench "$@" --csv "$tmp/o3.csv" > /dev/null || fail "mpirun bench --oracle"
  untimed "$tmp/o1.csv" > "$tmp/a"
  untimed "$tmp/o3.csv" > "$tmp/b"
  grep -q '^scenes/coincident.scene,S1,f64,.*,[0-9][0-9]*,[0-9][0-9]*,0,0.0000,' "$tmp/a" \
    || fail "bench --oracle: no oracle columns: $(cat "$tmp/a")"
  cmp -s "$tmp/a" "$tmp/b" || fail "bench --oracle: rows differ: $(diff "$tmp/a" "$tmp/b" | tr '\n' ' ')"
fi
if command -v gnuplot > /dev/null 2>&1; then
  mpi $mpibin bench scenes/csg.scene --size 16x16 --modes q16,f64 --runs 1 --threads 1 \
    --csv "$tmp/p.csv" --plot "$tmp/p.png" > /dev/null 2> "$tmp/e" || fail "mpirun bench --plot: $(cat "$tmp/e")"
  [ "$(head -c 4 "$tmp/p.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "bench: the chart is not a PNG"
fi
# A cell that fails (a bad deck among good ones) fails the job: one
# message, no CSV.
printf 'SPHERE S 1\nOBJECT T\n' > "$tmp/bad.scene"
mpi $mpibin bench scenes/csg.scene "$tmp/bad.scene" --size 16x16 --modes q16,f64 --runs 1 --threads 1 \
  --csv "$tmp/bad.csv" > /dev/null 2> "$tmp/e"; [ $? -eq 1 ] || fail "bench: bad deck: exit status"
[ "$(grep -c 'error:' "$tmp/e")" = 1 ] || fail "bench: bad deck: not one message: $(cat "$tmp/e")"
grep -q "bad.scene" "$tmp/e" || fail "bench: bad deck: the message does not name it: $(cat "$tmp/e")"
[ ! -e "$tmp/bad.csv" ] || fail "bench: bad deck wrote a CSV"

# A deck error is reported once (by rank 0) and fails every rank.
printf 'SPHERE S 1\nOBJECT T\n' > "$tmp/bad.scene"
mpi $mpibin render "$tmp/bad.scene" -o "$tmp/bad.png" 2> "$tmp/e" && fail "bad deck accepted"
[ "$(grep -c 'error:' "$tmp/e")" = 1 ] || fail "bad deck: not one message: $(cat "$tmp/e")"
[ ! -e "$tmp/bad.png" ] || fail "bad deck wrote a file"
# Kills rank 1 of the job started last (pid $job) half a second after it
# started, and checks that the job fails with a message; $1 names the job.
kill_rank1() {
  victim=""
  i=0
  while [ -z "$victim" ] && [ $i -lt 200 ]; do
    for p in /proc/[0-9]*; do
      { tr '\0' '\n' < "$p/environ" | grep -qx 'OMPI_COMM_WORLD_RANK=1'; } 2>/dev/null || continue
      grep -q "$tmp" "$p/cmdline" 2>/dev/null && victim=${p#/proc/}
    done
    i=$((i + 1))
    [ -n "$victim" ] || sleep 0.05
  done
  [ -n "$victim" ] || { kill $job; fail "$1: rank 1 never started"; }
  sleep 0.5
  kill -9 "$victim"
  wait $job && fail "$1: the job succeeded although rank 1 was killed"
  [ -s "$tmp/k.err" ] || fail "$1: no message when a rank died"
}
# Kill rank 1 while the ranks render: the job fails, nothing is written.
# The render is sized to last seconds (640x480 at --aa 3 ended within the
# half second on a fast host, its file written before the kill).
mpi $mpibin render $deck -o "$tmp/killed.png" --size 1280x960 --aa 4 --threads 1 \
  > "$tmp/k.out" 2> "$tmp/k.err" &
job=$!
kill_rank1 render
[ ! -e "$tmp/killed.png" ] || fail "output written although a rank died"
# The same mid-sweep: no CSV.
mpi $mpibin bench $deck scenes/csg.scene --size 320x240 --runs 3 --threads 1 --csv "$tmp/killed.csv" \
  > "$tmp/k.out" 2> "$tmp/k.err" &
job=$!
kill_rank1 bench
[ ! -e "$tmp/killed.csv" ] || fail "bench: CSV written although a rank died"
ls "$tmp" | grep -q 'tmp-' && fail "temporary file left behind"
exit 0
