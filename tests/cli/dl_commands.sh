#!/bin/sh
# maprt dl / dl2png: help, usage errors (exit 2), malformed input named by
# byte offset (exit 1), unknown backend, and encode -> validate -> dl2png on
# every backend giving the same picture.
set -u
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# Under the sanitizer build, leaks inside Mesa's libraries are not maprt's.
printf 'leak:libOSMesa.so\nleak:libEGL_mesa.so\nleak:swrast_dri.so\nleak:libLLVM\nleak:libglapi.so\n' > "$t/lsan.supp"
LSAN_OPTIONS="suppressions=$t/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export LSAN_OPTIONS

$MAPRT dl2png --help | grep -q -- '--backend B' || fail "dl2png --help"
$MAPRT dl --help | grep -q 'encode IN.png' || fail "dl --help"
$MAPRT dl2png only-one.dl5080 2>/dev/null; [ $? -eq 2 ] || fail "dl2png one argument"
$MAPRT dl2png a b --dac 5 2>/dev/null; [ $? -eq 2 ] || fail "dl2png --dac 5"
$MAPRT dl2png a b --backend x11 2>/dev/null; [ $? -eq 2 ] || fail "dl2png --backend x11"
$MAPRT dl frobnicate x 2>/dev/null; [ $? -eq 2 ] || fail "dl frobnicate"
$MAPRT dl dump 2>/dev/null; [ $? -eq 2 ] || fail "dl dump without file"
$MAPRT dl dump "$t/missing.dl5080" 2>/dev/null; [ $? -eq 1 ] || fail "dl dump missing file"

# A header with no end element: exit 1 naming offset 16.
printf '\304\323\365\360\370\360\000\001\000\000\000\010\000\010\000\000' > "$t/noend.dl5080"
$MAPRT dl validate "$t/noend.dl5080" 2> "$t/err"; [ $? -eq 1 ] || fail "validate noend status"
grep -qx "maprt: $t/noend.dl5080: offset 16: error: missing end element (0x5F02)" "$t/err" ||
  fail "validate noend message: $(cat "$t/err")"
$MAPRT dl2png "$t/noend.dl5080" "$t/x.png" 2>/dev/null; [ $? -eq 1 ] || fail "dl2png noend status"
[ ! -e "$t/x.png" ] || fail "dl2png left an output after an error"

# Round trip: a PNG made by dl2png from a hand-made list, re-encoded.
printf '\304\323\365\360\370\360\000\001\000\000\000\010\000\006\000\000' > "$t/a.dl5080"
printf '\000\024\137\000\000\000\000\003\000\000\000\377\000\377\000\000\000\000\377\000' >> "$t/a.dl5080"
printf '\000\006\137\001\000\000' >> "$t/a.dl5080"                    # clear 0 (blue)
printf '\000\006\120\123\000\001' >> "$t/a.dl5080"                    # interior colour 1
printf '\000\014\120\004\000\001\000\001\000\004\000\003' >> "$t/a.dl5080"  # fill 1,1-4,3
printf '\000\004\137\002' >> "$t/a.dl5080"                            # end
$MAPRT dl validate "$t/a.dl5080" | grep -q 'valid DL5080 version 1, 8x6' || fail "validate a"
$MAPRT dl dump "$t/a.dl5080" | grep -q '^     48     12  5004  fill-rect 1,1 4,3$' || fail "dump a"
for b in png osmesa egl; do
  $MAPRT dl2png "$t/a.dl5080" "$t/a-$b.png" --backend $b 2> "$t/err"
  rc=$?
  if [ $rc -eq 3 ]; then echo "skip $b: $(cat "$t/err")"; continue; fi
  [ $rc -eq 0 ] || fail "dl2png --backend $b: $(cat "$t/err")"
  cmp -s "$t/a-png.png" "$t/a-$b.png" || fail "backend $b differs from png"
done
$MAPRT dl encode "$t/a-png.png" "$t/b.dl5080" --dac 8 --stats > "$t/stats" || fail "encode"
grep -qx 'colours=2' "$t/stats" || fail "encode colours: $(cat "$t/stats")"
grep -qx 'psnr=1000000000.000' "$t/stats" || fail "encode psnr: $(cat "$t/stats")"
$MAPRT dl2png "$t/b.dl5080" "$t/b.png" --truecolor || fail "dl2png b"
$MAPRT dl encode "$t/b.png" "$t/c.dl5080" --dac 8 || fail "encode b"
cmp -s "$t/b.dl5080" "$t/c.dl5080" || fail "palette and true-colour PNGs encode differently"
exit 0
