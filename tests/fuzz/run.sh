#!/bin/sh
# Builds the library with clang and libFuzzer instrumentation (plus ASan/UBSan),
# links each tests/fuzz/fuzz_*.c against it and runs each for SECONDS seconds on
# its seed corpus (tests/fuzz/seeds/NAME). A crash, leak or timeout fails the run.
secs=${1:-15}
command -v clang >/dev/null 2>&1 || { echo "fuzz: clang not installed" >&2; exit 1; }
out=build-fuzz
san="-fsanitize=address,undefined -fno-sanitize-recover=all"
make --no-print-directory -s BUILD=$out CC=clang \
  CFLAGS="-O1 -g -fsanitize=fuzzer-no-link $san" $out/libmaprt.a || exit 1
libs=$(make --no-print-directory -s print-libs)
status=0
for f in tests/fuzz/fuzz_*.c; do
  [ -f "$f" ] || continue
  name=$(basename "$f" .c)
  clang -std=c99 -g -O1 -fopenmp -D_POSIX_C_SOURCE=200809L -Isrc -I. -fsanitize=fuzzer $san \
    -o $out/$name "$f" $out/libmaprt.a $libs || { status=1; continue; }
  mkdir -p $out/corpus-$name
  seeds=tests/fuzz/seeds/$name; [ -d "$seeds" ] || seeds=""
  if $out/$name -max_total_time="$secs" -timeout=10 -max_len=65536 -rss_limit_mb=2048 \
       $out/corpus-$name $seeds > $out/$name.log 2>&1; then
    echo "fuzz $name: $(grep -o 'Done [0-9]* runs in [0-9]* second' $out/$name.log | tail -1)"
  else
    echo "fuzz $name: FAILED (see $out/$name.log)"; tail -40 $out/$name.log; status=1
  fi
done
exit $status
