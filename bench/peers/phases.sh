#!/bin/sh
# make bench-phases: where the cost of n x n objects goes, phase by phase,
# in maprt (q16) and POV-Ray 3.7, on the scenes of bench/peers/grow.sh
# (GROW_TURN and GROW_VARY choose them as there; PHASES_N, default 100,
# the grid's side; GROW_SIZE the picture, default 512x384). Each round runs
# one object, then n x n, tool by tool; PHASES_RUNS rounds (default 7).
# The phases, all wall seconds of one thread:
#   load    maprt: the whole run at 1 x 1 pixels (reading, parsing and
#           compiling the deck, and the process's start and end);
#           POV-Ray: its "Parse Time" plus "Bounding Time"
#   render  maprt: --stats time.render_s; POV-Ray: its "Trace Time"
# Printed per phase: the medians at one object and at n x n, each tool's
# growth (the median of the ratios of the rounds' pairs), and the time
# each added object costs, (median at n x n - median at one) / (n^2 - 1),
# in microseconds. A whole run's growth weighs these by the tool's own
# cost at one object (make bench-grow).
# Usage: sh bench/peers/phases.sh [MAPRT [CPUTIME]]
dir=$(dirname "$0")
bin=${1:-build/maprt}
cputime=${2:-build/bench/cputime}
runs=${PHASES_RUNS:-7}
n=${PHASES_N:-100}
size=${GROW_SIZE:-512x384}
w=${size%x*}; h=${size#*x}
case $n in ''|*[!0-9]*|0|1) echo "bench-phases: PHASES_N must be a count above 1" >&2; exit 2 ;; esac
case $runs in ''|*[!0-9]*|0) echo "bench-phases: PHASES_RUNS must be a positive count" >&2; exit 2 ;; esac
command -v povray >/dev/null 2>&1 || { echo "bench-phases: povray (Debian povray) is not installed" >&2; exit 3; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/maprt-phases-XXXXXX") || exit 3
trap 'rm -rf "$tmp"' EXIT INT TERM
. "$dir/lib.sh"
need_timer

for k in 1 "$n"; do
  sh "$dir/grow.sh" --deck "$k" "$tmp/g$k.scene" && sh "$dir/grow.sh" --pov "$k" "$tmp/g$k.pov" || exit 3
done

# pov_phases K: one POV-Ray run of the K x K scene; appends its load
# (parse + bounding) and trace seconds to $tmp/pload$K and $tmp/ptrace$K
pov_phases() {
  povray "+I$tmp/g$1.pov" "+L$dir" "+O$tmp/p.png" "+W$w" "+H$h" +WT1 -D "File_Gamma=1.0" Display=off \
    > /dev/null 2> "$tmp/pov.err" || { echo "bench-phases: povray failed on $1 x $1" >&2; exit 3; }
  awk -v l="$tmp/pload$1" -v t="$tmp/ptrace$1" '
    /Parse Time:|Bounding Time:/ { s = $0; sub(/.*\(/, "", s); load += s + 0; got++ }
    /Trace Time:/ { s = $0; sub(/.*\(/, "", s); print s + 0 >> t; got++ }
    END { if (got != 3) exit 1; print load >> l }' "$tmp/pov.err" \
    || { echo "bench-phases: no phase times in POV-Ray's statistics" >&2; exit 3; }
}

i=0
while [ "$i" -lt "$runs" ]; do
  for k in 1 "$n"; do
    run "mload$k" "$bin" render "$tmp/g$k.scene" -o "$tmp/o.png" --size 1x1 --numeric q16 --threads 1 --quiet
    "$bin" render "$tmp/g$k.scene" -o "$tmp/o.png" --size "$size" --numeric q16 --threads 1 --quiet --stats \
      | sed -n 's/^time\.render_s=//p' >> "$tmp/mrender$k" || exit 3
    pov_phases "$k"
  done
  i=$((i + 1))
done
awk '{ print $2 }' "$tmp/mload1.t" > "$tmp/mload1"
awk '{ print $2 }' "$tmp/mload$n.t" > "$tmp/mload$n"

# mid FILE: the median of a file's values
mid() { sort -n "$1" | awk '{ v[NR] = $1 } END { printf "%.4f\n", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# pairs A B: the median of the rounds' ratios B / A
pairs() { paste -d ' ' "$1" "$2" | awk '$1 > 0 { print $2 / $1 }' > "$tmp/r"; mid "$tmp/r" | awk '{ printf "%.2f\n", $1 }'; }
# each A1 AN: microseconds an added object costs
each() { awk -v a="$1" -v b="$2" -v m="$((n * n - 1))" 'BEGIN { printf "%.2f\n", (b - a) / m * 1e6 }'; }

echo "phase,objects,maprt_1_s,maprt_n_s,pov_1_s,pov_n_s,maprt_growth,pov_growth,maprt_us_per_object,pov_us_per_object"
for p in load:mload:pload render:mrender:ptrace; do
  name=${p%%:*}; rest=${p#*:}; m=${rest%%:*}; v=${rest#*:}
  m1=$(mid "$tmp/${m}1"); mn=$(mid "$tmp/$m$n"); v1=$(mid "$tmp/${v}1"); vn=$(mid "$tmp/$v$n")
  echo "$name,$((n * n)),$m1,$mn,$v1,$vn,$(pairs "$tmp/${m}1" "$tmp/$m$n"),$(pairs "$tmp/${v}1" "$tmp/$v$n"),$(each "$m1" "$mn"),$(each "$v1" "$vn")"
done
