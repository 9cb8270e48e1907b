#!/bin/sh
# cms --help exits 0 and names every option; usage errors exit 2.
set -u
help=$("$MAPRT" cms --help) || { echo "--help failed"; exit 1; }
for opt in --disk --to --tape --punch --read-as --cp --read-cp --form --recfm --lrecl \
           import list type export MAPRT_DISK_ 'RC' vstream ebcdic punch rdw; do
  echo "$help" | grep -q -- "$opt" || { echo "--help does not mention $opt"; exit 1; }
done
for args in "" "frob" "type" "type A B C D E" "type X --cp 500" "type X --read-as cards" \
            "export A B --form rdw" "list --disk 1=x" "import --to 9 f" "type X --bogus" \
            "export A B --lrecl 0" "type X --to B" "list --form ebcdic" "import f --recfm F"; do
  # shellcheck disable=SC2086
  "$MAPRT" cms $args >/dev/null 2>&1; rc=$?
  [ $rc -eq 2 ] || { echo "'maprt cms $args' exited $rc, expected 2"; exit 1; }
done
exit 0
