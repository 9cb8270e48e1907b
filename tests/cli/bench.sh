#!/bin/sh
# maprt bench: table, CSV, the oracle columns, the Pareto chart, usage
# errors, and hostile scene names that must never reach a shell or gnuplot.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "bench.sh: $*" >&2; exit 1; }
case $MAPRT in /*) ;; *) MAPRT=$(pwd)/$MAPRT ;; esac
oracle=$(dirname "$MAPRT")/oracle/ids_oracle

$MAPRT bench --help | grep -q 'median wall-clock render seconds' || fail "--help"
$MAPRT bench scenes/fig1.scene --size 24x24 --modes q16,f64 --threads 1 --runs 3 --csv "$tmp/b.csv" > "$tmp/out" \
  || fail "bench failed"
[ "$(wc -l < "$tmp/b.csv")" -eq 3 ] || fail "CSV should hold a header and 2 rows"
head -1 "$tmp/b.csv" | grep -q '^scene,label,mode,threads,runs,seconds_median' || fail "CSV header"
grep -q '^scenes/fig1.scene,S1,f64,1,3,.*,inf,0.0000,0,0,0,,,,,,,0$' "$tmp/b.csv" || fail "f64 row should match its reference"
# The System/370 HFP modes: a row each, no exceptions beyond significance on fig1.
$MAPRT bench scenes/fig1.scene --size 24x24 --modes hfp32,hfp64 --runs 1 --threads 1 --csv "$tmp/h.csv" > /dev/null \
  || fail "bench hfp failed"
grep -q '^scenes/fig1.scene,S1,hfp32,1,1,.*,0,0,0,,,,,,,0$' "$tmp/h.csv" || fail "hfp32 row: $(cat "$tmp/h.csv")"
grep -q '^scenes/fig1.scene,S1,hfp64,1,1,.*,0,0,0,,,,,,,0$' "$tmp/h.csv" || fail "hfp64 row: $(cat "$tmp/h.csv")"
$MAPRT bench scenes/fig1.scene --modes q16,x 2> /dev/null; [ $? -eq 2 ] || fail "bad mode should exit 2"
$MAPRT bench scenes/fig1.scene --runs 0 2> /dev/null; [ $? -eq 2 ] || fail "--runs 0 should exit 2"
$MAPRT bench 2> /dev/null; [ $? -eq 2 ] || fail "no scene should exit 2"

if [ -x "$oracle" ]; then
  $MAPRT bench scenes/coincident.scene --size 32x32 --modes q16,f64 --threads 1 --runs 1 \
    --oracle "$oracle" --csv "$tmp/o.csv" > "$tmp/out" || fail "bench --oracle failed"
  grep -q '^scenes/coincident.scene,S1,f64,.*,0,0.0000,[0-9.e+-]*,[0-9.e+-]*,0$' "$tmp/o.csv" \
    || fail "f64 should match the oracle: $(cat "$tmp/o.csv")"
  $MAPRT bench scenes/coincident.scene --size 16x16 --runs 1 --oracle "$tmp/nonexistent" \
    > /dev/null 2>&1; [ $? -eq 3 ] || fail "a missing oracle should exit 3"
fi

# Hostile names: quotes and gnuplot's system(), backquotes, $(...), a
# newline. Nothing may run: no file named pwned* may appear anywhere.
mkdir "$tmp/work" || fail "mkdir"
n1="$tmp/x\";system(\"touch pwned1\");\".scene"
n2="$tmp/\`touch pwned2\`\$(touch pwned3)'; system('touch pwned4'); '.scene"
n3="$tmp/new
line\",\"q.scene"
for n in "$n1" "$n2" "$n3"; do cp scenes/coincident.scene "$n" || fail "cp"; done
p="$tmp/work/p'; system('touch pwned5'); '\";system(\"touch pwned6\");\".png"
set -- "$n1" "$n2" "$n3" --size 16x16 --modes q16,f64 --threads 1 --runs 1 --csv "$tmp/work/h.csv"
plot=0
if command -v gnuplot > /dev/null 2>&1; then plot=1; set -- "$@" --plot "$p"; fi
(cd "$tmp/work" && $MAPRT bench "$@" > out.txt 2> err.txt) \
  || fail "bench on hostile names failed: $(cat "$tmp/work/err.txt")"
[ -z "$(find "$tmp" . -name 'pwned*' 2> /dev/null)" ] || fail "a hostile name ran a command"
[ "$(grep -c ',S[123],' "$tmp/work/h.csv")" -eq 6 ] || fail "CSV rows of hostile names"
grep -q '^"'"$tmp"'/x"";system(""touch pwned1"");"".scene",S1,q16,' "$tmp/work/h.csv" || fail "CSV quoting"
if [ "$plot" = 1 ]; then
  [ "$(head -c 4 "$p" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "the chart is not a PNG"
  [ -z "$(ls "$tmp/work" | grep tmp)" ] || fail "a temporary file was left behind"
fi
exit 0
