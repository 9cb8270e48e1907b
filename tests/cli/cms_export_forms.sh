#!/bin/sh
# export --form ebcdic writes 80-byte cards (each record one card, blank
# padded; a longer record is refused, naming it); --form reader leads them
# with the CP ID card and a :READ card; export of a binary file as text is
# refused. Bytes are checked through glibc's iconv, an independent EBCDIC table.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
printf 'SPHERE S1 1.5\nEYE 0 -10 4\n' > "$d/fig1.scene"
"$MAPRT" cms export 'FIG1 SCENE A' "$d/fig1.ebc" --form ebcdic --disk A="$d" || fail "ebcdic export"
[ "$(wc -c < "$d/fig1.ebc")" -eq 160 ] || fail "ebcdic: $(wc -c < "$d/fig1.ebc") bytes, not 2 cards"
got=$(iconv -f IBM1047 -t ISO-8859-1 < "$d/fig1.ebc" | fold -w 80 | sed 's/ *$//')
[ "$got" = "$(printf 'SPHERE S1 1.5\nEYE 0 -10 4')" ] || fail "ebcdic cards: $got"
# a record of 81 columns does not fit a card
printf 'SHORT\n%081d\n' 0 > "$d/long.exec"
msg=$("$MAPRT" cms export 'LONG EXEC A' "$d/long.ebc" --form ebcdic --disk A="$d" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "long record: exit $rc"
case "$msg" in *"LONG EXEC A1:2:81: error: record of 81 bytes is longer than LRECL 80"*) ;; *) fail "long record: $msg";; esac
[ ! -e "$d/long.ebc" ] || fail "long record left an output"
# reader deck: ID card, :READ card, the cards
"$MAPRT" cms export 'FIG1 SCENE A' "$d/fig1.rdr" --form reader --userid maint --disk A="$d" || fail "reader export"
[ "$(wc -c < "$d/fig1.rdr")" -eq 320 ] || fail "reader: $(wc -c < "$d/fig1.rdr") bytes, not 4 cards"
got=$(iconv -f IBM1047 -t ISO-8859-1 < "$d/fig1.rdr" | fold -w 80 | sed 's/ *$//')
[ "$got" = "$(printf 'ID MAINT\n:READ  FIG1     SCENE    A1\nSPHERE S1 1.5\nEYE 0 -10 4')" ] || fail "reader deck: $got"
"$MAPRT" cms export 'FIG1 SCENE A' "$d/x.rdr" --form reader --disk A="$d" 2>/dev/null; rc=$?
[ $rc -eq 2 ] || fail "reader without --userid: exit $rc"
# a binary file is not written as text
"$MAPRT" cms import tests/fuzz/seeds/fuzz_cms_tape/dump --disk A="$d" >/dev/null || fail "seed import"
"$MAPRT" cms export 'RAY DATA A' "$d/ray.txt" --disk A="$d" 2>/dev/null; rc=$?
[ $rc -eq 2 ] || fail "binary as text: exit $rc"
"$MAPRT" cms export 'RAY DATA A' "$d/ray.bin" --form ebcdic --disk A="$d" || fail "binary as ebcdic"
cmp -s "$d/ray.data" "$d/ray.bin" || fail "binary ebcdic export is not the same bytes"
exit 0
