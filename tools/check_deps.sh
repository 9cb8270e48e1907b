#!/bin/sh
# Checks the include graph against the rooms of docs/architecture.md: every
# #include "dir/file.h" in src/, vm_cms_shim/ and display5080/ must name a
# header its room may use. Prints each violation as FILE:LINE: ROOM may not
# include HEADER, and exits 1 if there is any. With --graph it prints the
# room-level graph instead (ROOM -> ROOM, number of include lines).
set -u
set -f   # room lists hold "*"; no globbing
cd "$(dirname "$0")/.." || exit 2

# What each room may include besides itself and the C library: a list of
# rooms ("util") or single headers ("image/image.h").
allowed() {
  case $1 in
    util)        echo "" ;;
    num)         echo "util" ;;
    image)       echo "util" ;;
    model)       echo "util image/image.h" ;;
    geom)        echo "num model util image/image.h" ;;
    pds)         echo "num model util" ;;
    attr)        echo "geom num model util image/image.h" ;;
    render)      echo "num model util image/image.h" ;;
    trace)       echo "geom pds attr render num model util image/image.h" ;;
    scene)       echo "model util image/image.h" ;;
    compare)     echo "image util" ;;
    vm_cms_shim) echo "util" ;;
    display5080) echo "image util" ;;
    cli)         echo "*" ;;
    *)           echo "?" ;;
  esac
}

room_of() {   # src/geom/prim.c -> geom; vm_cms_shim/cms_tape.c -> vm_cms_shim
  d=${1%/*}
  echo "${d#src/}"
}

files=$(find src vm_cms_shim display5080 -name '*.[ch]' | LC_ALL=C sort)
bad=0
graph=$(mktemp) || exit 2
trap 'rm -f "$graph"' EXIT
for f in $files; do
  room=$(room_of "$f")
  ok=$(allowed "$room")
  grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$f" | while IFS= read -r line; do
    n=${line%%:*}
    h=$(printf '%s\n' "$line" | sed 's/.*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/')
    case $h in */*) hroom=${h%/*}; hroom=${hroom#src/} ;; *) hroom=$room ;; esac
    [ "$hroom" = "$room" ] && continue
    echo "$room -> $hroom" >> "$graph"
    pass=0
    for a in $ok; do
      { [ "$a" = "*" ] || [ "$a" = "$hroom" ] || [ "$a" = "$h" ]; } && pass=1
    done
    [ "$ok" = "?" ] && { echo "$f:$n: room $room is not in tools/check_deps.sh" ; continue; }
    [ $pass = 1 ] || echo "$f:$n: $room may not include $h"
  done
done > "$graph.out"
if [ "${1:-}" = "--graph" ]; then
  sort "$graph" | uniq -c | awk '{printf "%-12s -> %-12s %3d\n", $2, $4, $1}'
  rm -f "$graph.out"
  exit 0
fi
if [ -s "$graph.out" ]; then
  cat "$graph.out" >&2
  echo "check-deps: $(wc -l < "$graph.out") include(s) cross the rules of docs/architecture.md" >&2
  bad=1
else
  echo "check-deps: $(echo "$files" | wc -l) files follow docs/architecture.md"
fi
rm -f "$graph.out"
exit $bad
