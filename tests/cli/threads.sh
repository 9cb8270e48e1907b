#!/bin/sh
# --threads N bounds every thread a render starts, the PNG encoder's too,
# and OMP_NUM_THREADS those of merge's and dl2png --truecolor's PNG
# encoder: counted as the threads the process creates (clone/clone3 with
# CLONE_THREAD under strace) and those that end before it (exit), N - 1
# and none, with the same PNG bytes for N = 1 and 2. Where N is the CPUs
# the process may use, the team that keeps one thread on each starts one
# thread more, which ends before the work (src/util/cpubind.c): N and one.
# Exit 77 (skipped) without strace.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "threads.sh: $*" >&2; exit 1; }
command -v strace >/dev/null 2>&1 || { echo "skipped: needs strace (apt-get install -y strace)"; exit 77; }
# LeakSanitizer cannot stop the world under a tracer; ASan builds run
# without leak checks here (the rest of the suite has them)
export ASAN_OPTIONS=detect_leaks=0 SOURCE_DATE_EPOCH=536457600
# threads LABEL T CMD...: CMD run under strace starts T - 1 threads beside
# the first and ends none; where T (>= 2) is the CPUs, the team that keeps
# one thread on each CPU starts T and ends one
threads() {
  label=$1 t=$2; shift 2
  strace -f -qq -e trace=clone,clone3,exit -o "$tmp/trace" "$@" || fail "$label: failed"
  n=$(grep -c 'CLONE_THREAD' "$tmp/trace")
  ended=$(grep -c ' exit(0)' "$tmp/trace")
  want=$((t - 1)) want_ended=0
  if [ "$t" -ge 2 ] && [ "$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)" -eq "$t" ]; then
    want=$t want_ended=1
  fi
  [ "$n" -eq "$want" ] && [ "$ended" -eq "$want_ended" ] \
    || fail "$label started $n threads and ended $ended, not $want and $want_ended: $(cat "$tmp/trace")"
}
$MAPRT render scenes/fig1.scene --size 96x512 --region 0,0,96,256 --part "$tmp/a.part" --quiet \
  && $MAPRT render scenes/fig1.scene --size 96x512 --dl "$tmp/d.dl5080" --quiet \
  && $MAPRT render scenes/fig1.scene --size 96x512 --region 0,256,96,512 --part "$tmp/b.part" --quiet \
  || fail "the parts could not be rendered"
for t in 1 2; do
  threads "--threads $t" $t $MAPRT render scenes/fig1.scene -o "$tmp/t$t.png" --size 96x512 --threads $t --quiet
  # merge and dl2png --truecolor: their PNG encoder's threads (OMP_NUM_THREADS)
  threads "merge on $t" $t env OMP_NUM_THREADS=$t $MAPRT merge "$tmp/a.part" "$tmp/b.part" -o "$tmp/m$t.png"
  threads "dl2png on $t" $t env OMP_NUM_THREADS=$t $MAPRT dl2png "$tmp/d.dl5080" "$tmp/d$t.png" --truecolor
done
cmp -s "$tmp/t1.png" "$tmp/t2.png" || fail "the PNG differs between --threads 1 and 2"
cmp -s "$tmp/m1.png" "$tmp/m2.png" || fail "merge: the PNG differs between 1 and 2 threads"
cmp -s "$tmp/d1.png" "$tmp/d2.png" || fail "dl2png: the PNG differs between 1 and 2 threads"
