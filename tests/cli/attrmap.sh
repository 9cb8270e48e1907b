#!/bin/sh
# Attribute mapping through the CLI: every shipped deck renders in every
# mode and looks up its PDS; images named by a deck are found beside it, by
# host path and on a CMS disk by fileid in any case; a missing image is an
# input error naming the deck's record and the file.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail() { echo "attrmap.sh: $*" >&2; exit 1; }

for s in fig1 pds-cpg pds-pixel pds-cells pds-quadtree pds-striptree pds-bspline glass granite foil; do
  for m in q16 q32 f32 f64; do
    "$MAPRT" render "scenes/$s.scene" -o "$tmp/$s.png" --size 48x36 --numeric $m --stats \
      > "$tmp/stats" || fail "$s $m did not render"
    n=$(sed -n 's/^pds.lookups=//p' "$tmp/stats")
    [ "$n" -gt 0 ] || fail "$s $m: no PDS lookups"
    o=$(sed -n 's/^fx.overflows=//p' "$tmp/stats")
    [ "$o" -eq 0 ] || fail "$s $m: $o fixed-point overflows"
  done
done

# The foil deck's label image on a CMS disk: deck and image by fileid, the
# image's host name in upper case.
mkdir "$tmp/disk"
cp scenes/foil.scene "$tmp/disk/foil.scene"
cp scenes/label.png "$tmp/disk/LABEL.PNG"
"$MAPRT" render 'FOIL SCENE B' --disk "B=$tmp/disk" -o "$tmp/foil-b.png" --size 32x32 \
  || fail "deck and image by fileid"

# A missing image: exit 1, the record and column of the name, the file.
sed 's/label.png/nothere.png/' scenes/foil.scene > "$tmp/bad.scene"
"$MAPRT" render "$tmp/bad.scene" -o "$tmp/bad.png" --size 8x8 2> "$tmp/err"
[ $? -eq 1 ] || fail "missing image should exit 1"
grep -q "^maprt: $tmp/bad.scene:[0-9]*:[0-9]*: error: TEXTURE: cannot read nothere.png" "$tmp/err" \
  || fail "missing image message: $(cat "$tmp/err")"
[ -e "$tmp/bad.png" ] && fail "output written for a failed render"
exit 0
