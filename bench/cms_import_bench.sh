#!/bin/sh
# Import of a VMFPLC2 tape of N small files (default 10,000), the time
# `maprt cms import` takes, wall and CPU. The tape is written by
# `maprt cms export --form aws` from N one-record host files.
# usage: sh bench/cms_import_bench.sh [N] [MAPRT]
set -u
n=${1:-10000}
maprt=${2:-build/maprt}
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
mkdir "$d/src" "$d/dst"
i=0
while [ $i -lt $n ]; do
  printf 'RECORD OF FILE %d\n' $i > "$d/src/f$i.data"
  i=$((i + 1))
done
(cd "$d/src" && ls | tr 'a-z' 'A-Z' | sed 's/^\(.*\)\.\(.*\)$/\1 \2 A/') > "$d/names"
tr '\n' '\0' < "$d/names" | xargs -0 sh -c '"$0" cms export "$@" '"$d/t.aws"' --form aws --disk A='"$d/src" "$maprt" ||
  { echo "export failed"; exit 1; }
echo "tape: $(wc -c < "$d/t.aws") bytes, $n files"
/usr/bin/time -f "import: %e s wall, %U s user, %S s system" "$maprt" cms import "$d/t.aws" --disk A="$d/dst" |
  tail -1
