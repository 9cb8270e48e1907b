#!/bin/sh
# Imports the AWS tapes kept as fuzz seeds (CMS TAPE DUMP with a null block and
# a short trailer; VMFPLC2) and reads records back. The null block of the dump
# tape is a hole of 800 zeros where records 11 and 12 lie, so that file is
# binary: kept byte for byte by default, skipped or refused on request.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
seeds=tests/fuzz/seeds/fuzz_cms_tape
out=$("$MAPRT" cms import $seeds/dump --disk A="$d") || { echo "import failed: $out"; exit 1; }
expect="RAY DATA A1          F    80       12 records  (tape dump, binary: byte X'00' at record 11 column 1, 1 null block, 1987-11-22 10:15)
1 file imported to disk A"
[ "$out" = "$expect" ] || { printf 'import printed:\n%s\n' "$out"; exit 1; }
[ "$(wc -c < "$d/ray.data")" -eq 960 ] || { echo "binary file is not 12 x 80 bytes"; exit 1; }
# records 11-12 are the hole: 80 zero bytes each
[ "$(dd if="$d/ray.data" bs=80 skip=10 2>/dev/null | od -An -v -tx1 | tr -d ' \n' | tr -d 0)" = "" ] ||
  { echo "hole is not zeros"; exit 1; }
"$MAPRT" cms list --disk A="$d" | grep -q '^RAY      DATA     A1 F    80       12  binary$' ||
  { echo "list does not show the binary file"; exit 1; }
[ "$("$MAPRT" cms type 'RAY DATA A' --disk A="$d" | sed -n 1p | cut -c1-24)" = "     1 D3C9D5C5 40F04040" ] ||
  { echo "type does not show hex"; exit 1; }
# --binary fail names record and column; nothing is left behind
rm -f "$d"/ray.data*
msg=$("$MAPRT" cms import $seeds/dump --disk A="$d" --binary fail 2>&1); rc=$?
[ $rc -eq 1 ] || { echo "--binary fail: exit $rc"; exit 1; }
case "$msg" in *"dump(RAY DATA A1):11:1: error: byte X'00' is not text"*) ;; *) echo "fail message: $msg"; exit 1;; esac
[ -z "$(ls "$d")" ] || { echo "--binary fail left files: $(ls "$d")"; exit 1; }
out=$("$MAPRT" cms import $seeds/dump --disk A="$d" --binary skip) || exit 1
case "$out" in *"binary, skipped"*"0 files imported"*) ;; *) echo "skip printed: $out"; exit 1;; esac
# the VMFPLC2 tape is text
out=$("$MAPRT" cms import $seeds/vmfplc2 --disk C="$d" --to C) || { echo "import failed: $out"; exit 1; }
expect='PLCF DATA C1         F    80       12 records  (vmfplc2, code page 1047, 1987-11-22 10:15)
1 file imported to disk C'
[ "$out" = "$expect" ] || { printf 'import printed:\n%s\n' "$out"; exit 1; }
[ "$("$MAPRT" cms type 'PLCF DATA C' --disk C="$d" | sed -n 12p)" = "LINE 11" ] || { echo "record 12"; exit 1; }
# importing again needs --replace
"$MAPRT" cms import $seeds/vmfplc2 --disk C="$d" --to C >/dev/null 2>&1; rc=$?
[ $rc -eq 1 ] || { echo "second import without --replace: exit $rc"; exit 1; }
"$MAPRT" cms import $seeds/vmfplc2 --disk C="$d" --to C --replace >/dev/null || { echo "--replace"; exit 1; }
# a tape cut short is refused and leaves no file behind
head -c 1000 $seeds/dump > "$d/cut.aws"
"$MAPRT" cms import "$d/cut.aws" --disk A="$d" 2>/dev/null; rc=$?
[ $rc -eq 1 ] || { echo "cut tape: exit $rc"; exit 1; }
[ ! -e "$d/ray.data" ] || { echo "cut tape left a file"; exit 1; }
[ -z "$(ls -a "$d" | grep maprt-import)" ] || { echo "staging directory left behind"; exit 1; }
exit 0
