#!/bin/sh
# One drawing budget for every display-list backend: 64 clears of a
# 4096x4096 screen (2^30 pixel steps, the default budget exactly) draw the
# same picture on png, osmesa and egl; 2,000 and 100,000 clears are refused
# by all three at the 65th clear (byte offset 16 + 64*6 = 400), exit 1, with
# the same message. A GL backend that cannot start here is reported and the
# script exits 77 after the others ran (CI installs them all).
set -u
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
fail() { echo "dl_budget.sh: $*" >&2; exit 1; }
. tests/need.sh
gl_leaks_not_ours "$t"

# clears N FILE: a 4096x4096 version 1 list of N clears (colour 5) and an end.
printf '\000\006\137\001\000\005' > "$t/one"
i=0; cp "$t/one" "$t/many"
while [ $i -lt 17 ]; do cat "$t/many" "$t/many" > "$t/m2"; mv "$t/m2" "$t/many"; i=$((i + 1)); done
clears() {
  { printf '\304\323\365\360\370\360\000\001\000\000\020\000\020\000\000\000'
    head -c $(($1 * 6)) "$t/many"; printf '\000\004\137\002'; } > "$2"
}
clears 64 "$t/c64.dl5080"
clears 2000 "$t/c2000.dl5080"
clears 100000 "$t/c100k.dl5080"
$MAPRT dl validate "$t/c100k.dl5080" | grep -q '4096x4096.*clear=100000 end=1' || fail "c100k is not 100000 clears"

msg="maprt: $t/LIST: offset 400: error: drawing work limit of 1073741824 pixel steps exceeded"
skipped=
for b in png osmesa egl; do
  $MAPRT dl2png "$t/c64.dl5080" "$t/c64-$b.png" --backend $b 2> "$t/err"
  rc=$?
  if [ $rc -eq 3 ] && [ $b != png ]; then skipped="$skipped $b: $(cat "$t/err")"; continue; fi
  [ $rc -eq 0 ] || fail "$b: 64 clears: exit $rc: $(cat "$t/err")"
  cmp -s "$t/c64-png.png" "$t/c64-$b.png" || fail "$b: 64 clears differ from png"
  for l in c2000.dl5080 c100k.dl5080; do
    $MAPRT dl2png "$t/$l" "$t/x-$b.png" --backend $b 2> "$t/err"
    rc=$?
    [ $rc -eq 1 ] || fail "$b: $l: exit $rc, expected 1: $(cat "$t/err")"
    grep -qxF "$(echo "$msg" | sed "s|LIST|$l|")" "$t/err" || fail "$b: $l: message $(cat "$t/err")"
    [ ! -e "$t/x-$b.png" ] || fail "$b: $l: output left behind"
  done
done
if [ -n "$skipped" ]; then
  echo "skipped: needs the GL backends (apt-get install -y libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri):$skipped"
  exit 77
fi
exit 0
