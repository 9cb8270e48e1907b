#!/bin/sh
# maprt dl / dl2png: help, usage errors (exit 2), malformed input named by
# byte offset (exit 1), unknown backend, and encode -> validate -> dl2png on
# every backend giving the same picture.
set -u
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
. tests/need.sh
gl_leaks_not_ours "$t"

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
# A raw MegaPel FIFO image as IBM's driver writes it: no header, no end
# element. It converts with --raw on every backend to the same picture.
: > "$t/f.fifo"
printf '\000\006\120\141\000\000' >> "$t/f.fifo"   # plane mask reset (all planes)
printf '\000\006\120\123\000\001' >> "$t/f.fifo"   # interior colour 1
printf '\000\014\120\004\000\001\000\001\000\004\000\003' >> "$t/f.fifo"   # fill 1,1-4,3
printf '\000\026\120\030\000\002\000\005\000\004\000\006\000\010\000\004\001\002\003\004\005\006' >> "$t/f.fifo"   # BLT 3x2, rows top-first, packed
printf '\000\014\120\015\000\000\000\000\000\002\301\302' >> "$t/f.fifo"   # text "AB" in EBCDIC at 0,0
printf '\000\024\120\022\000\020\200\000\000\000\000\000\000\003\000\001\000\010\000\004' >> "$t/f.fifo"   # BLT from adapter memory
$MAPRT dl validate "$t/f.fifo" 2> "$t/err"; [ $? -eq 1 ] || fail "fifo without --raw"
grep -q 'bad magic; a raw MegaPel stream needs --raw' "$t/err" || fail "fifo message: $(cat "$t/err")"
$MAPRT dl validate "$t/f.fifo" --size 16x8 2>/dev/null; [ $? -eq 2 ] || fail "--size without --raw"
$MAPRT dl dump "$t/a.dl5080" --dac 8 2>/dev/null; [ $? -eq 2 ] || fail "dump --dac without --raw"
$MAPRT dl validate "$t/f.fifo" --raw --size 16x8 > "$t/out" || fail "validate --raw"
grep -q "valid raw MegaPel stream, 16x8, 8-bit DAC, 78 bytes, 6 elements: fill-rect=1 text=1 src-blt=1 blt=1" "$t/out" ||
  fail "validate --raw: $(cat "$t/out")"
$MAPRT dl validate "$t/f.fifo" --raw | grep -q ', 1024x1024, 8-bit DAC' || fail "raw default size"
$MAPRT dl dump "$t/f.fifo" --raw --dac 4 > "$t/out" || fail "dump --raw"
grep -qx '      0      0  ----  raw MegaPel stream dac=4 size=1024x1024' "$t/out" || fail "dump raw head: $(head -1 "$t/out")"
grep -qx '      0      6  5061  plane-mask 0x0000 (writes planes 0xFF)' "$t/out" || fail "dump raw mask"
grep -qx '     58     20  5012  src-blt addr=0x00108000 0,0 3,1 bpp=8 op=4 (pixels in adapter memory)' "$t/out" ||
  fail "dump raw src-blt"
for b in png osmesa egl; do
  $MAPRT dl2png "$t/f.fifo" "$t/f-$b.png" --raw --size 16x8 --backend $b 2> "$t/err"
  rc=$?
  if [ $rc -eq 3 ]; then echo "skip $b: $(cat "$t/err")"; continue; fi
  [ $rc -eq 0 ] || fail "dl2png --raw --backend $b: $(cat "$t/err")"
  grep -qx "maprt: $t/f.fifo: offset 58: warning: 1 block transfer from adapter memory (0x5012) not drawn: a stream does not carry their pixels" "$t/err" ||
    fail "src-blt warning: $(cat "$t/err")"
  cmp -s "$t/f-png.png" "$t/f-$b.png" || fail "raw: backend $b differs from png"
done
exit 0
