#!/bin/sh
# A Hercules ASCII punch deck with two :READ files -> import -> list -> type;
# export as EBCDIC cards, V stream and punch deck, and read each back.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
mkdir "$d/a" "$d/b"
printf '%s\n' ':READ  FIG1     SCENE    A1 VOL001 11/22/87  10:15' \
  '* FIGURE 1 [TEST] 2^3                                                  FIG00010' \
  'SPHERE S1 1.5                                                          FIG00020' \
  ':READ  NOTES    TEXT     A1' 'HELLO' > "$d/deck.punch"
out=$("$MAPRT" cms import "$d/deck.punch" --disk B="$d/b" --to B) || { echo "import failed: $out"; exit 1; }
expect='FIG1 SCENE B1        F    80        2 records  (punch)
NOTES TEXT B1        F    80        1 records  (punch)
2 files imported to disk B'
[ "$out" = "$expect" ] || { printf 'import printed:\n%s\n' "$out"; exit 1; }
[ -f "$d/b/fig1.scene" ] && [ -f "$d/b/notes.text" ] || { echo "host files missing"; ls "$d/b"; exit 1; }
out=$("$MAPRT" cms list B --disk B="$d/b") || exit 1
expect='FILENAME FILETYPE FM F LRECL  RECORDS  FORM
FIG1     SCENE    B1 F    80        2  text
NOTES    TEXT     B1 F    80        1  text'
[ "$out" = "$expect" ] || { printf 'list printed:\n%s\n' "$out"; exit 1; }
want=$(sed -n '2,3p' "$d/deck.punch")
got=$("$MAPRT" cms type 'fig1 scene *' --disk B="$d/b") || exit 1
[ "$got" = "$want" ] || { printf 'type printed:\n%s\n' "$got"; exit 1; }
for form in ebcdic vstream punch text; do
  for cp in 037 1047; do
    "$MAPRT" cms export 'FIG1 SCENE B' "OUT $form A" --form $form --cp $cp \
      --disk B="$d/b" --disk A="$d/a" || { echo "export $form failed"; exit 1; }
    got=$("$MAPRT" cms type "OUT $form A" --disk A="$d/a" --cp $cp) || { echo "type $form failed"; exit 1; }
    [ "$got" = "$want" ] || { printf '%s %s read back:\n%s\n' $form $cp "$got"; exit 1; }
  done
done
[ "$(wc -c < "$d/a/out.ebcdic")" -eq 160 ] || { echo "ebcdic deck is not 2 cards"; exit 1; }
[ "$(wc -c < "$d/a/out.vstream")" -eq 164 ] || { echo "V stream of F 80 is not 2 x 82 bytes"; exit 1; }
head -n 1 "$d/a/out.punch" | grep -q '^:READ  FIG1     SCENE    B1$' || { echo "punch header"; exit 1; }
# the punch export imports again as the same file
out=$("$MAPRT" cms import "$d/a/out.punch" --disk A="$d/a") || exit 1
echo "$out" | grep -q '^FIG1 SCENE A1 ' || { echo "re-import: $out"; exit 1; }
ls "$d/a" | grep -q tmp && { echo "temporary file left behind"; exit 1; }
exit 0
