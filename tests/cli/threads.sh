#!/bin/sh
# --threads N bounds every thread a render starts, the PNG encoder's too:
# counted as the threads the process creates (clone/clone3 with
# CLONE_THREAD under strace), 0 for --threads 1 and 1 for --threads 2, with
# the same PNG bytes either way. Exit 77 (skipped) without strace.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "threads.sh: $*" >&2; exit 1; }
command -v strace >/dev/null 2>&1 || { echo "skipped: needs strace (apt-get install -y strace)"; exit 77; }
# LeakSanitizer cannot stop the world under a tracer; ASan builds run
# without leak checks here (the rest of the suite has them)
export ASAN_OPTIONS=detect_leaks=0 SOURCE_DATE_EPOCH=536457600
for t in 1 2; do
  strace -f -qq -e trace=clone,clone3 -o "$tmp/trace$t" \
    $MAPRT render scenes/fig1.scene -o "$tmp/t$t.png" --size 96x512 --threads $t --quiet \
    || fail "--threads $t: render failed"
  n=$(grep -c 'CLONE_THREAD' "$tmp/trace$t")
  [ "$n" -eq $((t - 1)) ] || fail "--threads $t started $n threads, not $((t - 1)): $(cat "$tmp/trace$t")"
done
cmp -s "$tmp/t1.png" "$tmp/t2.png" || fail "the PNG differs between --threads 1 and 2"
