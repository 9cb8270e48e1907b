#!/bin/sh
# --threads N bounds every thread a render starts, the PNG encoder's too:
# counted as the threads the process creates (clone/clone3 with
# CLONE_THREAD under strace) less those that end before it (exit), 0 for
# --threads 1 and 1 for --threads 2, with the same PNG bytes either way.
# Where N is the CPUs the process may use, the team that keeps one thread
# on each starts one thread more, which ends before the render
# (src/util/cpubind.c). Exit 77 (skipped) without strace.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "threads.sh: $*" >&2; exit 1; }
command -v strace >/dev/null 2>&1 || { echo "skipped: needs strace (apt-get install -y strace)"; exit 77; }
# LeakSanitizer cannot stop the world under a tracer; ASan builds run
# without leak checks here (the rest of the suite has them)
export ASAN_OPTIONS=detect_leaks=0 SOURCE_DATE_EPOCH=536457600
for t in 1 2; do
  strace -f -qq -e trace=clone,clone3,exit -o "$tmp/trace$t" \
    $MAPRT render scenes/fig1.scene -o "$tmp/t$t.png" --size 96x512 --threads $t --quiet \
    || fail "--threads $t: render failed"
  n=$(grep -c 'CLONE_THREAD' "$tmp/trace$t")
  ended=$(grep -c ' exit(0)' "$tmp/trace$t")
  most=$((t - 1))
  [ "$t" -ge 2 ] && [ "$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)" -eq "$t" ] && most=$t
  [ "$n" -le "$most" ] && [ $((n - ended)) -eq $((t - 1)) ] \
    || fail "--threads $t started $n threads and ended $ended, not $((t - 1)) working: $(cat "$tmp/trace$t")"
done
cmp -s "$tmp/t1.png" "$tmp/t2.png" || fail "the PNG differs between --threads 1 and 2"
