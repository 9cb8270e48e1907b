#!/bin/sh
# The timing tools of the benchmarks: bench/peers/cputime records "cpu
# wall user system" with cpu = user + system; tools/ab.sh alternates two
# binaries and reports both and their ratio; bench/peers/grow.sh --deck N
# writes bench-grow's n x n deck, which maprt reads, and --pov N its
# POV-Ray scene (with GROW_TURN=1 each part turned its own way, the deck
# within 72 columns); both refuse a bad N and a file they read as the
# output. bench/peers/phases.sh, run against a stand-in for POV-Ray that
# prints its phase times, reports them and their growth per phase.
# Exit 77 (skipped) without a C compiler.
set -u
cc=${CC:-cc}
command -v "$cc" >/dev/null 2>&1 || { echo "skipped: needs a C compiler ($cc)"; exit 77; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "bench_tools.sh: $*" >&2; exit 1; }
"$cc" -std=c99 -O2 -o "$tmp/cputime" bench/peers/cputime.c || fail "bench/peers/cputime.c did not build"

"$tmp/cputime" "$tmp/t" sh -c 'i=0; while [ $i -lt 20000 ]; do i=$((i + 1)); done' || fail "cputime: the command failed"
awk 'NF != 4 || $1 < 0 || $2 <= 0 || $1 - $3 - $4 > 2e-6 || $3 + $4 - $1 > 2e-6 { bad = 1 } END { exit bad || NR != 1 }' "$tmp/t" \
  || fail "cputime's record is not cpu wall user system: $(cat "$tmp/t")"
"$tmp/cputime" "$tmp/t" sh -c 'exit 3'; [ $? -eq 3 ] || fail "cputime does not pass on the command's status"

sh bench/peers/grow.sh --deck 3 "$tmp/g3.scene" || fail "grow.sh --deck 3 failed"
[ "$(grep -c '^OBJECT PART ' "$tmp/g3.scene")" -eq 9 ] || fail "the 3 x 3 deck does not hold 9 objects"
$MAPRT render "$tmp/g3.scene" -o "$tmp/g3.png" --size 16x12 --threads 1 --quiet || fail "maprt does not read the 3 x 3 deck"
cp bench/peers/csg81.scene "$tmp/csg81.before"
sh bench/peers/grow.sh --deck 0 "$tmp/g0.scene" 2>/dev/null && fail "grow.sh --deck 0 succeeded"
sh bench/peers/grow.sh --deck x "$tmp/gx.scene" 2>/dev/null && fail "grow.sh --deck x succeeded"
sh bench/peers/grow.sh --deck 2 bench/peers/csg81.scene 2>/dev/null && fail "grow.sh --deck wrote over the deck it reads"
cmp -s bench/peers/csg81.scene "$tmp/csg81.before" || fail "bench/peers/csg81.scene changed"
[ -e "$tmp/g0.scene" ] || [ -e "$tmp/gx.scene" ] && fail "a refused --deck left a file"
grep -q "^OBJECT PART .*ROTATE" "$tmp/g3.scene" && fail "the grid's deck turns its parts without GROW_TURN"
GROW_TURN=1 sh bench/peers/grow.sh --deck 3 "$tmp/t3.scene" || fail "GROW_TURN=1 grow.sh --deck 3 failed"
[ "$(grep '^OBJECT PART ' "$tmp/t3.scene" | awk '{ print $7, $10 }' | sort -u | wc -l)" -eq 9 ] \
  || fail "the turned 3 x 3 deck does not turn its 9 parts each its own way"
[ "$(grep -c '^  ROTATE Z ' "$tmp/t3.scene")" -eq 9 ] || fail "the turned deck's continuation cards are missing"
awk 'length($0) > 72 { exit 1 }' "$tmp/t3.scene" || fail "the turned deck has a card beyond column 72"
$MAPRT render "$tmp/t3.scene" -o "$tmp/t3.png" --size 16x12 --threads 1 --quiet || fail "maprt does not read the turned deck"
GROW_TURN=1 sh bench/peers/grow.sh --pov 3 "$tmp/t3.pov" || fail "GROW_TURN=1 grow.sh --pov 3 failed"
[ "$(grep -c '^object { Part scale .* rotate <.* rotate <0, .* rotate <0, 0, ' "$tmp/t3.pov")" -eq 9 ] \
  || fail "the turned POV-Ray scene does not turn its 9 parts"
sh bench/peers/grow.sh --pov 3 "$tmp/g3.pov" || fail "grow.sh --pov 3 failed"
[ "$(grep -c '^object { Part scale ' "$tmp/g3.pov")" -eq 9 ] || fail "the 3 x 3 POV-Ray scene does not hold 9 parts"
grep -q '^#include "csg.inc"' "$tmp/g3.pov" || fail "the POV-Ray scene does not include csg.inc"
cp bench/peers/csg81.pov "$tmp/csg81.pov.before"
sh bench/peers/grow.sh --pov 2 bench/peers/csg81.pov 2>/dev/null && fail "grow.sh --pov wrote over the scene it reads"
cmp -s bench/peers/csg81.pov "$tmp/csg81.pov.before" || fail "bench/peers/csg81.pov changed"

out=$(CPUTIME="$tmp/cputime" sh tools/ab.sh 2 $MAPRT $MAPRT render "$tmp/g3.scene" -o "$tmp/ab.png" --size 16x12 --threads 1 --quiet) \
  || fail "tools/ab.sh failed"
for w in "old: cpu median" "new: cpu median" "new/old: medians"; do
  printf '%s\n' "$out" | grep -q "^$w" || fail "tools/ab.sh printed no '$w': $out"
done
err=$(CPUTIME="$tmp/cputime" sh tools/ab.sh x "$MAPRT" "$MAPRT" --version 2>&1 >/dev/null) \
  && fail "tools/ab.sh took a count that is not one"
printf '%s\n' "$err" | grep -q "N must be a count" || fail "tools/ab.sh on a bad count: $err"
mkdir "$tmp/bin"
cat > "$tmp/bin/povray" <<'POV'
#!/bin/sh
# stands in for POV-Ray 3.7: its statistics' phase lines on standard error,
# 1 x 1 parts parsed in 0.010 s and bounded at once, 2 x 2 in 0.030 + 0.002
case $1 in *g1.pov) p=0.010 b=0.000 t=0.300 ;; *) p=0.030 b=0.002 t=0.330 ;; esac
echo "  Parse Time:       0 hours  0 minutes  0 seconds ($p seconds)" >&2
echo "  Bounding Time:    0 hours  0 minutes  0 seconds ($b seconds)" >&2
echo "  Trace Time:       0 hours  0 minutes  0 seconds ($t seconds)" >&2
POV
chmod +x "$tmp/bin/povray"
out=$(PATH="$tmp/bin:$PATH" PHASES_N=2 PHASES_RUNS=1 GROW_SIZE=16x12 sh bench/peers/phases.sh "$MAPRT" "$tmp/cputime") \
  || fail "phases.sh failed: $out"
printf '%s\n' "$out" | grep -q '^load,4,[0-9.]*,[0-9.]*,0.0100,0.0320,[0-9.]*,3.20,[-0-9.]*,7333.33$' \
  || fail "phases.sh's load row: $out"
printf '%s\n' "$out" | grep -q '^render,4,[0-9.]*,[0-9.]*,0.3000,0.3300,[0-9.]*,1.10,[-0-9.]*,10000.00$' \
  || fail "phases.sh's render row: $out"
PATH="$tmp/bin:$PATH" PHASES_N=1 sh bench/peers/phases.sh "$MAPRT" "$tmp/cputime" 2>/dev/null \
  && fail "phases.sh took PHASES_N=1"
echo "ok: cputime's record, tools/ab.sh, grow.sh --deck and --pov, phases.sh"
