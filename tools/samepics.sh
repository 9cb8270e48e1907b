#!/bin/sh
# usage: sh tools/samepics.sh OLD_MAPRT NEW_MAPRT [SIZE] [MODES]
# Renders every deck of scenes/, bench/ and bench/peers/ with both binaries
# in each numeric mode (default: all six, 96x72, one thread) and compares
# the decoded pixels byte for byte (the PPM's comment lines, which carry
# the date, are dropped). Prints one line per deck and mode that differs
# and a closing count; exit 1 when any differs or fails.
old=$1 new=$2 size=${3:-96x72}
modes=${4:-q16 q32 f32 f64 hfp32 hfp64}
[ -x "$old" ] && [ -x "$new" ] || { echo "usage: samepics.sh OLD_MAPRT NEW_MAPRT [SIZE] [MODES]" >&2; exit 2; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/samepics-XXXXXX") || exit 3
trap 'rm -rf "$tmp"' EXIT INT TERM
pixels() {   # BIN DECK MODE OUT: the picture's pixel bytes without comments
  "$1" render "$2" -o - --format ppm --size "$size" --numeric "$3" --threads 1 --quiet 2>"$4.err" |
    sed '1,/^255$/{/^#/d}' > "$4"
}
n=0 bad=0
for deck in scenes/*.scene bench/*.scene bench/peers/*.scene; do
  for m in $modes; do
    n=$((n + 1))
    pixels "$old" "$deck" "$m" "$tmp/a"; sa=$?
    pixels "$new" "$deck" "$m" "$tmp/b"; sb=$?
    if ! cmp -s "$tmp/a" "$tmp/b" || ! cmp -s "$tmp/a.err" "$tmp/b.err"; then
      bad=$((bad + 1)); echo "differs: $deck $m"
    fi
  done
done
echo "samepics: $bad of $n renders differ ($size)"
[ "$bad" -eq 0 ]
