#!/bin/sh
# The wrong kind of file is named, with the command that reads it, by every
# command that takes one; cms list notes and skips host files that are not
# CMS files.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "sniff.sh: $*" >&2; exit 1; }
expect() {   # expect EXIT MESSAGE command...
  want=$1 msg=$2; shift 2
  "$@" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq "$want" ] || fail "$* exited $rc, not $want: $(cat "$tmp/err")"
  grep -qxF "$msg" "$tmp/err" || fail "$*: want '$msg', got: $(cat "$tmp/err")"
}
$MAPRT render scenes/csg.scene --size 8x8 -o "$tmp/a.png" --dl "$tmp/a.dl5080" || fail "setup render"
printf '\014\000\000\000\240\000abcdefghijkl' > "$tmp/t.aws"     # one 12-byte block
printf '\037\213\010\000' > "$tmp/x.gz"

expect 1 "maprt: $tmp/a.png: error: this is a PNG image, not a scene deck; did you mean \`maprt compare\`?" \
  $MAPRT render "$tmp/a.png" -o "$tmp/b.png"
expect 1 "maprt: $tmp/a.dl5080: error: this is a DL5080 display list, not a scene deck; did you mean \`maprt dl2png\`?" \
  $MAPRT render "$tmp/a.dl5080" -o "$tmp/b.png"
expect 1 "maprt: $tmp/t.aws: error: this is a Hercules AWS tape image, not a scene deck; did you mean \`maprt cms import --tape\`?" \
  $MAPRT render "$tmp/t.aws" -o "$tmp/b.png"
expect 1 "maprt: $tmp/x.gz: error: this is a gzip-compressed file, not a scene deck" \
  $MAPRT render "$tmp/x.gz" -o "$tmp/b.png"
expect 1 "maprt: $tmp/a.png: error: this is a PNG image, not a card deck or a tape; did you mean \`maprt compare\`?" \
  $MAPRT cms import "$tmp/a.png" --disk "A=$tmp"
expect 1 "maprt: $tmp/a.png: error: this is a PNG image, not a DL5080 display list; did you mean \`maprt compare\`?" \
  $MAPRT dl2png "$tmp/a.png" "$tmp/c.png"
expect 1 "maprt: scenes/csg.scene: error: this is a text file, not a DL5080 display list; did you mean \`maprt render\`?" \
  $MAPRT dl dump scenes/csg.scene
expect 1 "maprt: $tmp/a.dl5080: error: this is a DL5080 display list, not a PNG image; did you mean \`maprt dl2png\`?" \
  $MAPRT dl encode "$tmp/a.dl5080" "$tmp/d.dl5080"
expect 1 "maprt: scenes/csg.scene: error: this is a text file, not a picture (PNG, PNM, JPEG or TIFF); did you mean \`maprt render\`?" \
  $MAPRT compare scenes/csg.scene "$tmp/a.png"

# cms list: a PNG on the disk is noted and skipped, the decks are listed, exit 0
mkdir "$tmp/disk" && cp scenes/csg.scene "$tmp/disk/" && cp "$tmp/a.png" "$tmp/disk/label.png"
$MAPRT cms list --disk "A=$tmp/disk" > "$tmp/out" 2> "$tmp/err" || fail "cms list failed: $(cat "$tmp/err")"
grep -q '^CSG  *SCENE  *A1' "$tmp/out" || fail "csg.scene not listed: $(cat "$tmp/out")"
grep -qx "maprt: note: LABEL PNG A1 skipped: a PNG image, not a CMS file" "$tmp/err" || fail "no note: $(cat "$tmp/err")"
exit 0
