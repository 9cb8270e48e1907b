#!/bin/sh
# The tracer is built twice where the compiler can (the Makefile's ISA_V3):
# for the baseline and for x86-64-v3, taken at run time where the processor
# runs it. Both must draw the same picture, bit for bit, in every numeric
# mode: every deck of scenes/ and bench/peers/ at 48x36 with --isa
# baseline and with --isa auto, the pixel bytes compared. Also --isa's
# errors and --stats' isa line. Exit 77 (skipped) where auto gives the
# baseline (no x86-64-v3 build or processor): there is nothing to compare.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "isa.sh: $*" >&2; exit 1; }
deck=bench/peers/csg1.scene

$MAPRT render "$deck" -o "$tmp/x.ppm" --isa avx2 2>"$tmp/err"
[ $? -eq 2 ] || fail "--isa avx2: exit status is not 2"
grep -q "'avx2' is not auto or baseline" "$tmp/err" || fail "--isa avx2: $(cat "$tmp/err")"
$MAPRT render "$deck" -o "$tmp/x.ppm" --isa 2>/dev/null
[ $? -eq 2 ] || fail "--isa without a value: exit status is not 2"

isa_of() {   # ISA: the isa line of --stats
  $MAPRT render "$deck" -o "$tmp/x.ppm" --size 8x6 --isa "$1" --stats --quiet | sed -n 's/^isa=//p'
}
[ "$(isa_of baseline)" = baseline ] || fail "--isa baseline: --stats says isa=$(isa_of baseline)"
[ "$(isa_of BASELINE)" = baseline ] || fail "--isa BASELINE is not taken as baseline"
auto=$(isa_of auto)
case $auto in
  x86-64-v3) ;;
  baseline) echo "skipped: this build or processor has no x86-64-v3 code (--isa auto runs the baseline)"; exit 77 ;;
  *) fail "--isa auto: --stats says isa=$auto" ;;
esac

# the pixel bytes of a PPM, without its comment lines
pixels() { sed '1,/^255$/{/^#/d}' "$1"; }
n=0
for d in scenes/*.scene bench/peers/*.scene; do
  for m in q16 q32 f32 f64 hfp32 hfp64; do
    for isa in baseline auto; do
      $MAPRT render "$d" -o "$tmp/$isa.ppm" --size 48x36 --numeric "$m" --threads 1 --isa "$isa" \
        --quiet 2>"$tmp/$isa.err" || fail "$d $m --isa $isa: $(cat "$tmp/$isa.err")"
      pixels "$tmp/$isa.ppm" > "$tmp/$isa.px"
    done
    cmp -s "$tmp/baseline.px" "$tmp/auto.px" || fail "$d $m: x86-64-v3 and baseline pictures differ"
    cmp -s "$tmp/baseline.err" "$tmp/auto.err" || fail "$d $m: x86-64-v3 and baseline warnings differ"
    n=$((n + 1))
  done
done
echo "ok: x86-64-v3 and baseline draw the same $n pictures; --isa checked"
