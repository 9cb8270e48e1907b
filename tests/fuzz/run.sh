#!/bin/sh
# usage: run.sh SECONDS [keep]
# Builds the library with clang and libFuzzer instrumentation (plus ASan/UBSan),
# links each tests/fuzz/fuzz_*.c against it (FUZZ_TARGETS="fuzz_a fuzz_b"
# picks some) and runs each for SECONDS seconds (or FUZZ_RUNS executions,
# whichever comes first) on its seeds
# (tests/fuzz/seeds/NAME) and its kept corpus (tests/fuzz/corpus/NAME).
#  - without "keep" (CI's smoke run): new inputs go to build-fuzz/corpus-NAME;
#  - with "keep" (make fuzz): new inputs join the kept corpus, which is then
#    minimised in place (-merge=1: the fewest inputs that keep its coverage)
#    and trimmed to FUZZ_KEEP_BYTES (24 KB) per target, largest inputs first.
# Prints "fuzz NAME: Done N runs in S second(s)" per target. A crash, leak or
# timeout fails the run.
secs=${1:-15}
keep=${2:-}
command -v clang >/dev/null 2>&1 || { echo "fuzz: clang not installed" >&2; exit 1; }
out=build-fuzz
top=$(pwd)   # absolute paths: a target may change directory (fuzz_cli does)
san="-fsanitize=address,undefined -fno-sanitize-recover=all"
make --no-print-directory -s BUILD=$out CC=clang \
  CFLAGS="-O1 -g -fsanitize=fuzzer-no-link $san" $out/libmaprt.a || exit 1
libs=$(make --no-print-directory -s print-libs)
opts="-timeout=10 -max_len=65536 -rss_limit_mb=2048 -print_final_stats=0 -close_fd_mask=3 -artifact_prefix=$top/$out/"
status=0
for f in tests/fuzz/fuzz_*.c; do
  [ -f "$f" ] || continue
  name=$(basename "$f" .c)
  if [ -n "${FUZZ_TARGETS:-}" ]; then
    case " $FUZZ_TARGETS " in *" $name "*) ;; *) continue ;; esac
  fi
  clang -std=c99 -g -O1 -fopenmp -D_POSIX_C_SOURCE=200809L -Isrc -I. -fsanitize=fuzzer $san \
    -o $out/$name "$f" $out/libmaprt.a $libs || { status=1; continue; }
  seeds=$top/tests/fuzz/seeds/$name; [ -d "$seeds" ] || seeds=""
  kept=$top/tests/fuzz/corpus/$name
  mkdir -p "$kept"
  if [ -n "$keep" ]; then new=$kept; else new=$top/$out/corpus-$name; mkdir -p "$new"; fi
  bin=$top/$out/$name   # absolute: libFuzzer re-runs itself for -merge
  if $bin -max_total_time="$secs" ${FUZZ_RUNS:+-runs=$FUZZ_RUNS} $opts "$new" $( [ "$new" = "$kept" ] || echo "$kept" ) $seeds \
       > $out/$name.log 2>&1; then
    echo "fuzz $name: $(grep -o 'Done [0-9]* runs in [0-9]* second' $out/$name.log | tail -1)"
  else
    echo "fuzz $name: FAILED (see $out/$name.log)"; tail -40 $out/$name.log; status=1
    continue
  fi
  if [ -n "$keep" ]; then
    min=$top/$out/min-$name
    rm -rf "$min" && mkdir -p "$min"
    if $bin -merge=1 $opts "$min" "$kept" $seeds > $out/$name.merge.log 2>&1 &&
       { [ -n "$(ls "$min")" ] || [ -z "$(ls "$kept")" ]; }; then
      rm -rf "$kept" && mv "$min" "$kept"
      # the repository keeps at most FUZZ_KEEP_BYTES per target: the largest
      # inputs go first (the seeds keep the real files)
      while [ "$(cat "$kept"/* 2>/dev/null | wc -c)" -gt "${FUZZ_KEEP_BYTES:-24576}" ]; do
        rm -f "$(ls -S "$kept"/* | head -1)"
      done
      echo "fuzz $name: kept corpus $(ls "$kept" | wc -l) inputs, $(cat "$kept"/* 2>/dev/null | wc -c) bytes"
    else
      echo "fuzz $name: minimising failed (see $out/$name.merge.log)"; status=1
    fi
  fi
done
exit $status
