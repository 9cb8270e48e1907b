#!/bin/sh
# Outputs never destroy inputs, are checked before the work, commit all or
# none; inputs that are directories, FIFOs or devices are refused without
# blocking; size bombs are refused from the header; stdout write errors and
# thread-creation failure give the contract's exit codes.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "hostile_files.sh: $*" >&2; exit 1; }
# expect CODE TEXT CMD...: exit status CODE and a stderr line containing TEXT
expect() {
  code=$1 text=$2; shift 2
  "$@" > /dev/null 2> "$tmp/err"; rc=$?
  [ "$rc" -eq "$code" ] || fail "$*: exit $rc, expected $code: $(cat "$tmp/err")"
  grep -qF -- "$text" "$tmp/err" || fail "$*: message '$(cat "$tmp/err")' lacks '$text'"
}
cp scenes/csg.scene "$tmp/d.scene"
sum() { cksum "$1" | cut -d' ' -f1,2; }
before=$(sum "$tmp/d.scene")

# An output that is an input is refused before the work (exit 2), also
# through a symbolic or a hard link, and the input is unchanged.
expect 2 "the name must end in .png, .ppm or .pam" $MAPRT render "$tmp/d.scene" -o "$tmp/d.scene" --size 8x8
ln -s d.scene "$tmp/sym.png"; ln "$tmp/d.scene" "$tmp/hard.png"
expect 2 "is an input of this command" $MAPRT render "$tmp/d.scene" -o "$tmp/sym.png" --size 8x8
expect 2 "is an input of this command" $MAPRT render "$tmp/d.scene" --dl "$tmp/hard.png" --size 8x8
[ "$(sum "$tmp/d.scene")" = "$before" ] || fail "the deck was overwritten"
[ -L "$tmp/sym.png" ] || fail "the symlink was replaced"
# ... an image the deck names is an input too
cp scenes/foil.scene scenes/label.png "$tmp/"
lbefore=$(sum "$tmp/label.png")
expect 2 "is an input of this command" $MAPRT render "$tmp/foil.scene" -o "$tmp/label.png" --size 8x8
[ "$(sum "$tmp/label.png")" = "$lbefore" ] || fail "the texture was overwritten"
# ... for every command that writes
$MAPRT render "$tmp/d.scene" -o "$tmp/a.png" --dl "$tmp/a.dl" --size 16x16 || fail "render failed"
dbefore=$(sum "$tmp/a.dl")
expect 2 "so its name must end in .png" $MAPRT dl2png "$tmp/a.dl" "$tmp/a.dl"
[ "$(sum "$tmp/a.dl")" = "$dbefore" ] || fail "dl2png overwrote its input"
expect 2 "is an input of this command" $MAPRT dl encode "$tmp/a.png" "$tmp/a.png"
cp "$tmp/a.png" "$tmp/t.png"
pbefore=$(sum "$tmp/a.png")
expect 2 "is an input of this command" $MAPRT compare "$tmp/a.png" "$tmp/t.png" --diff "$tmp/a.png"
expect 2 "is an input of this command" $MAPRT compare "$tmp/a.png" "$tmp/t.png" --side-by-side "$tmp/t.png"
[ "$(sum "$tmp/a.png")" = "$pbefore" ] || fail "compare overwrote its reference"
printf 'HELLO\n' > "$tmp/c"
expect 2 "is an input of this command" $MAPRT cms export "$tmp/c" "$tmp/c"
[ "$(cat "$tmp/c")" = HELLO ] || fail "cms export overwrote its input"
# Two outputs on one file are refused too.
expect 2 "is also the output" $MAPRT render "$tmp/d.scene" -o "$tmp/same.png" --dl "$tmp/same.png" --size 8x8
expect 2 "is also the output" $MAPRT compare "$tmp/a.png" "$tmp/t.png" --diff "$tmp/x.png" --side-by-side "$tmp/./x.png"

# A symlink planted at the temporary name the old scheme predicted
# (OUT.tmp-PID-1; exec keeps the shell's PID) is not followed: the victim
# keeps its bytes, the output is a new regular file.
printf 'precious' > "$tmp/victim"
sh -c 'ln -s "$1" "$2.tmp-$$-1" && exec "$3" render "$4" -o "$2" --size 8x8' sh "$tmp/victim" "$tmp/out.png" \
  $MAPRT "$tmp/d.scene" || fail "render with a planted symlink failed"
[ "$(cat "$tmp/victim")" = precious ] || fail "the planted symlink was followed"
[ -f "$tmp/out.png" ] && [ ! -L "$tmp/out.png" ] || fail "no regular output"
rm -f "$tmp"/out.png.tmp-* "$tmp/out.png"

# Output directories are checked before the work: this render would take
# hours (16384x16384, 16x16 samples a pixel); refused at once instead.
expect 3 "directory $tmp/none" $MAPRT render "$tmp/d.scene" -o "$tmp/none/x.png" --size 16384x16384 --aa 16
mkdir -p "$tmp/adir.png"
expect 3 "is a directory" $MAPRT render "$tmp/d.scene" -o "$tmp/adir.png" --size 16384x16384 --aa 16
expect 3 "directory $tmp/none" $MAPRT render "$tmp/d.scene" -o "$tmp/ok.png" --dl "$tmp/none/x.dl" --size 16384x16384 --aa 16
expect 3 "directory $tmp/none" $MAPRT compare "$tmp/a.png" "$tmp/t.png" --diff "$tmp/none/d.png"
expect 3 "directory $tmp/none" $MAPRT dl2png "$tmp/a.dl" "$tmp/none/x.png"
[ -e "$tmp/ok.png" ] && fail "-o written although --dl could not be"
# All or none: the display list fails while being written (file size limit,
# SIGXFSZ ignored so that write reports EFBIG), so the PNG is not kept either.
$MAPRT render "$tmp/d.scene" -o "$tmp/s.png" --size 16x16 || fail "small render failed"
$MAPRT render "$tmp/d.scene" --dl "$tmp/s.dl" --wireframe --size 128x128 || fail "dl render failed"
png_kb=$(( ($(wc -c < "$tmp/s.png") + 1023) / 1024 ))
dl_kb=$(( $(wc -c < "$tmp/s.dl") / 1024 ))
rm -f "$tmp/s.png" "$tmp/s.dl"
[ "$dl_kb" -gt "$png_kb" ] || fail "test set-up: the display list ($dl_kb KB) must be larger than the PNG ($png_kb KB)"
( trap '' XFSZ; ulimit -f $((png_kb * 2)); exec $MAPRT render "$tmp/d.scene" -o "$tmp/s.png" --dl "$tmp/s.dl" \
    --wireframe --size 128x128 ) 2> "$tmp/err"; rc=$?
[ "$rc" -eq 3 ] || fail "a failed --dl write should exit 3, got $rc: $(cat "$tmp/err")"
[ -e "$tmp/s.png" ] || [ -e "$tmp/s.dl" ] && fail "an output was kept although the other failed"
ls "$tmp" | grep -q 'tmp-' && fail "temporary file left behind: $(ls "$tmp")"

# Inputs: a directory is bad input (1); a FIFO with no writer and a device
# are refused at once (a FIFO read would block for ever).
mkdir "$tmp/dir"; mkfifo "$tmp/fifo"
expect 1 "is a directory, not a regular file" $MAPRT render "$tmp/dir" -o "$tmp/x.png"
expect 1 "is a directory, not a regular file" $MAPRT dl dump "$tmp/dir"
expect 1 "is a FIFO, not a regular file" timeout 20 $MAPRT compare "$tmp/fifo" "$tmp/a.png"
expect 1 "is a FIFO, not a regular file" timeout 20 $MAPRT dl2png "$tmp/fifo" "$tmp/x.png"
expect 1 "is a device, not a regular file" $MAPRT compare /dev/zero "$tmp/a.png"
printf 'TEXTURE T IMAGE /dev/zero\n' > "$tmp/zero.scene"
expect 1 "is a device, not a regular file" $MAPRT render "$tmp/zero.scene" -o "$tmp/x.png"
# A 99-byte PNG that claims 20000x20000 pixels (400 M, 1.2 GB decoded) is
# refused from its header, as a texture, as a compare input and by dl encode.
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\116\040\000\000\116\040\010\000\000\000\000\306\033\031\345\000\000\000\052\111\104\101\124\170\234\355\301\061\001\000\000\000\302\240\365\117\155\015\017\240\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\270\060\116\041\000\001\076\265\325\265\000\000\000\000\111\105\116\104\256\102\140\202' > "$tmp/bomb.png"
[ "$(wc -c < "$tmp/bomb.png")" -eq 99 ] || fail "test set-up: bomb.png"
printf 'TEXTURE T IMAGE bomb.png\n' > "$tmp/bomb.scene"
expect 1 "image size 20000x20000 is over the limit of 32768 per side and 16777216 pixels" \
  $MAPRT render "$tmp/bomb.scene" -o "$tmp/x.png"
expect 1 "image size 20000x20000 is over the limit" $MAPRT compare "$tmp/bomb.png" "$tmp/a.png"
expect 1 "image size 20000x20000 is over the limit of 4096 per side" $MAPRT dl encode "$tmp/bomb.png" "$tmp/x.dl"

# stdout write errors are I/O failures (exit 3).
if [ -c /dev/full ]; then
  $MAPRT render "$tmp/d.scene" -o "$tmp/x.png" --size 8x8 --stats > /dev/full 2> "$tmp/err"; rc=$?
  [ "$rc" -eq 3 ] || fail "--stats to /dev/full: exit $rc"
  grep -q "^maprt: <stdout>: error: write failed: No space left on device" "$tmp/err" || fail "stdout message: $(cat "$tmp/err")"
  $MAPRT dl dump "$tmp/a.dl" > /dev/full 2> /dev/null; [ $? -eq 3 ] || fail "dl dump to /dev/full should exit 3"
  $MAPRT compare "$tmp/a.png" "$tmp/t.png" > /dev/full 2> /dev/null; [ $? -eq 3 ] || fail "compare to /dev/full should exit 3"
  # ... also where maprt itself, not a subcommand, writes: help and version
  for a in --help help --version; do
    $MAPRT $a > /dev/full 2> /dev/null; [ $? -eq 3 ] || fail "maprt $a to /dev/full should exit 3"
  done
fi
# A render thread that cannot be created (1 GB stacks under a 400 MB address
# space): libgomp ends the process itself, with status 1; maprt turns that
# into the contract's 3 and removes its temporaries. (A sanitizer build,
# whose shadow memory needs more address space, cannot start under the limit
# at all: the case is left to the plain build there.)
if ( ulimit -v 400000; exec $MAPRT --version ) > /dev/null 2>&1; then
  ( ulimit -v 400000; OMP_STACKSIZE=1G exec $MAPRT render "$tmp/d.scene" -o "$tmp/th.png" --size 32x32 --threads 2 ) \
    2> "$tmp/err"; rc=$?
  [ "$rc" -eq 3 ] || fail "thread-creation failure: exit $rc, expected 3: $(cat "$tmp/err")"
  grep -q "^libgomp: Thread creation failed" "$tmp/err" || fail "thread-creation message: $(cat "$tmp/err")"
  grep -qx "maprt: error: a library ended the run (the line above says why)" "$tmp/err" ||
    fail "thread-creation message: $(cat "$tmp/err")"
  [ ! -e "$tmp/th.png" ] || fail "an output was written although no thread could start"
fi
ls "$tmp" | grep -q 'tmp-' && fail "temporary file left behind: $(ls "$tmp")"
exit 0
