#!/bin/sh
# maprt compare: every bad input is a clear located error with exit 1, every
# bad command line a usage error with exit 2, and --help tells the truth.
set -u
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
fail() { echo "compare_errors: $*" >&2; exit 1; }

# expect STATUS MESSAGE ARGS...: runs compare, checks exit status and stderr
expect() {
  want=$1 msg=$2; shift 2
  err=$("$MAPRT" compare "$@" 2>&1 >/dev/null); rc=$?
  [ "$rc" = "$want" ] || fail "compare $*: exit $rc, want $want ($err)"
  [ "$err" = "$msg" ] || fail "compare $*: said '$err', want '$msg'"
}

printf 'P2\n12 12\n255\n' > "$t/a.pgm"
i=0; while [ $i -lt 144 ]; do printf '%d\n' $((i % 251)); i=$((i + 1)); done >> "$t/a.pgm"
printf 'P2\n13 12\n255\n' > "$t/b.pgm"
i=0; while [ $i -lt 156 ]; do printf '%d\n' $((i % 7)); i=$((i + 1)); done >> "$t/b.pgm"
: > "$t/empty.png"
printf 'hello\n' > "$t/text.png"
printf 'P5\n0 12\n255\n' > "$t/zero.pgm"
printf 'P5\n4 4\n255\nxx' > "$t/short.pgm"
printf 'P2\n12 12\n255\n' > "$t/flat.pgm"
i=0; while [ $i -lt 144 ]; do printf '7\n'; i=$((i + 1)); done >> "$t/flat.pgm"

"$MAPRT" compare "$t/a.pgm" "$t/a.pgm" > /dev/null || fail "a good pair failed"
expect 1 "maprt: $t/missing.png: error: cannot open: No such file or directory" "$t/missing.png" "$t/a.pgm"
expect 1 "maprt: $t/missing.png: error: cannot open: No such file or directory" "$t/a.pgm" "$t/missing.png"
expect 1 "maprt: $t/empty.png: error: empty file (not a PNG, PNM, JPEG or TIFF image)" "$t/empty.png" "$t/a.pgm"
expect 1 "maprt: $t/text.png: error: this is a text file, not a picture (PNG, PNM, JPEG or TIFF); did you mean \`maprt render\`?" "$t/a.pgm" "$t/text.png"
expect 1 "maprt: $t/zero.pgm: error: image size 0x12 is empty" "$t/zero.pgm" "$t/a.pgm"
expect 1 "maprt: $t/short.pgm: offset 13: error: raster truncated: 2 bytes present, 16 needed" "$t/short.pgm" "$t/a.pgm"
expect 1 "maprt: $t: error: is a directory, not a regular file" "$t" "$t/a.pgm"
expect 1 "maprt: $t/b.pgm: error: size 13x12 differs from the reference's 12x12; use --register to compare pictures of different sizes" "$t/a.pgm" "$t/b.pgm"
expect 1 "maprt: $t/flat.pgm: error: the picture is one flat tone: there is nothing to register on" "$t/a.pgm" "$t/flat.pgm" --register
expect 1 "maprt: $t/a.pgm: error: crop 5,5,10,10 is not inside the 12x12 reference" "$t/a.pgm" "$t/a.pgm" --crop 5,5,10,10

usage() { "$MAPRT" compare "$@" > /dev/null 2>&1; [ $? = 2 ] || fail "compare $*: not a usage error"; }
usage
usage "$t/a.pgm"
usage "$t/a.pgm" "$t/a.pgm" "$t/a.pgm"
usage "$t/a.pgm" "$t/a.pgm" --bogus
usage "$t/a.pgm" "$t/a.pgm" --threshold 300
usage "$t/a.pgm" "$t/a.pgm" --threshold
usage "$t/a.pgm" "$t/a.pgm" --descreen -1
usage "$t/a.pgm" "$t/a.pgm" --crop 1,2,3
usage "$t/a.pgm" "$t/a.pgm" --crop 1,2,3,0
usage "$t/a.pgm" "$t/a.pgm" --scale-range 2,1
usage "$t/a.pgm" "$t/a.pgm" --max-angle 90

help=$("$MAPRT" compare --help) || fail "--help failed"
for s in --register --scale-range --max-angle --crop --grey --descreen --levels --threshold --diff --side-by-side \
         "K1=0.01, K2=0.03" "sigma 1.5" "11x11" "Rec. 601" "peak 255" "default 8" "default 0.25,4" "default 5"; do
  printf '%s\n' "$help" | grep -q -e "$s" || fail "--help does not mention '$s'"
done
exit 0
