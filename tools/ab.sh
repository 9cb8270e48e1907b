#!/bin/sh
# usage: sh tools/ab.sh N OLD NEW ARG...
# Two maprt binaries timed on the same arguments, alternated: N rounds of
# OLD ARG... then NEW ARG..., each run through bench/peers' timer (user and
# system time of the child alone, microseconds; CPUTIME overrides
# build/bench/cputime, which `make build/bench/cputime` builds). Prints for
# each binary the median and minimum CPU and the medians of user and
# system time, then NEW / OLD by the medians and by the minima. On a
# shared machine this resolves changes that runs minutes apart cannot
# (docs/performance.md); for changes inside the tracer, instruction counts
# (tools/icount.sh) are the steadier measure.
n=${1:?usage: ab.sh N OLD NEW ARG...}
old=${2:?usage: ab.sh N OLD NEW ARG...}
new=${3:?usage: ab.sh N OLD NEW ARG...}
shift 3
cputime=${CPUTIME:-build/bench/cputime}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/maprt-ab-XXXXXX") || exit 3
trap 'rm -rf "$tmp"' EXIT INT TERM
. "$(dirname "$0")/../bench/peers/lib.sh"
need_timer
case $n in ''|*[!0-9]*) echo "ab: N must be a count of rounds" >&2; exit 2 ;; esac
i=0
while [ "$i" -lt "$n" ]; do
  run old "$old" "$@"
  run new "$new" "$@"
  i=$((i + 1))
done
for b in old new; do
  echo "$b: cpu median $(med "$b" 1) min $(least "$b" 1); user median $(med "$b" 3); system median $(med "$b" 4)"
done
awk -v a="$(med old 1)" -v b="$(med new 1)" -v c="$(least old 1)" -v d="$(least new 1)" \
  'BEGIN { printf "new/old: medians %.3f, minima %.3f\n", (a > 0 ? b / a : 0), (c > 0 ? d / c : 0) }'
