#!/bin/sh
# The drawing budget is counted once, in the interpreter, so every backend
# refuses the same list at the same element: 2000 full-screen clears of a
# 4096x4096 screen (12 KB of list, 33 G pixel steps) used to take 93 s on
# osmesa; now png, osmesa and egl all stop at the 64th clear (the screen's
# own initial clear counts too) with the same message.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "dl_work.sh: $*" >&2; exit 1; }
# header: magic "DL5080" in EBCDIC, version 1, flags 0, 4096 x 4096, reserved
printf '\304\323\365\360\370\360\000\001\000\000\020\000\020\000\000\000' > "$tmp/clears.dl"
i=0
while [ $i -lt 2000 ]; do printf '\000\006\137\001\000\001'; i=$((i + 1)); done >> "$tmp/clears.dl"
printf '\000\004\137\002' >> "$tmp/clears.dl"
[ "$(wc -c < "$tmp/clears.dl")" -eq 12020 ] || fail "test set-up: list size"
$MAPRT dl validate "$tmp/clears.dl" > /dev/null || fail "the list is well formed and should validate"
# 63 clears and the initial one fit in 2^30 steps (64 x 16 M); the 64th
# clear, at offset 16 + 63 * 6, goes over.
printf '\304\323\365\360\370\360\000\001\000\000\020\000\020\000\000\000\000\006\137\001\000\001\000\006\137\001\000\001\000\006\077\077\000\001\000\004\137\002' > "$tmp/bad.dl"
want="maprt: $tmp/clears.dl: offset 394: error: drawing work limit of 1073741824 pixel steps exceeded"
for b in png osmesa egl; do
  timeout 60 $MAPRT dl2png "$tmp/clears.dl" "$tmp/$b.png" --backend $b 2> "$tmp/err"; rc=$?
  if [ "$rc" -eq 3 ] && grep -q "built without\|cannot\|EGL" "$tmp/err"; then
    echo "dl_work.sh: backend $b not available here: $(cat "$tmp/err")" >&2; continue
  fi
  [ "$rc" -eq 1 ] || fail "$b: exit $rc, expected 1: $(cat "$tmp/err")"
  [ "$(cat "$tmp/err")" = "$want" ] || fail "$b: message '$(cat "$tmp/err")'"
  [ -e "$tmp/$b.png" ] && fail "$b: output written for a refused list"
  # a list refused after drawing has started: a clean error (osmesa used to
  # crash in OSMesaDestroyContext with the clears still in flight)
  $MAPRT dl2png "$tmp/bad.dl" "$tmp/$b.png" --backend $b 2> "$tmp/err"; rc=$?
  [ "$rc" -eq 1 ] || fail "$b: refused list after drawing: exit $rc: $(cat "$tmp/err")"
  grep -qx "maprt: $tmp/bad.dl: offset 28: error: unknown element code 0x3F3F" "$tmp/err" || fail "$b: $(cat "$tmp/err")"
done
exit 0
