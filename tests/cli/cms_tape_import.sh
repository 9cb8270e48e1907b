#!/bin/sh
# Imports the AWS tapes kept as fuzz seeds (CMS TAPE DUMP with a null block and
# a short trailer; VMFPLC2) and reads a record back.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
seeds=tests/fuzz/seeds/fuzz_cms_tape
out=$("$MAPRT" cms import $seeds/dump --disk A="$d") || { echo "import failed: $out"; exit 1; }
expect='RAY DATA A1          F    80       12 records  (tape dump, code page 1047)
1 file imported to disk A'
[ "$out" = "$expect" ] || { printf 'import printed:\n%s\n' "$out"; exit 1; }
out=$("$MAPRT" cms import $seeds/vmfplc2 --disk C="$d" --to C) || { echo "import failed: $out"; exit 1; }
expect='PLCF DATA C1         F    80       12 records  (vmfplc2, code page 1047)
1 file imported to disk C'
[ "$out" = "$expect" ] || { printf 'import printed:\n%s\n' "$out"; exit 1; }
[ "$("$MAPRT" cms type 'RAY DATA A' --disk A="$d" | sed -n 12p)" = "LINE 11" ] || { echo "record 12"; exit 1; }
cmp -s "$d/ray.data" "$d/plcf.data" || { echo "the two tapes hold the same records"; exit 1; }
# a tape cut short is refused and leaves no file behind
head -c 1000 $seeds/dump > "$d/cut.aws"
rm -f "$d/ray.data"
"$MAPRT" cms import "$d/cut.aws" --disk A="$d" 2>/dev/null; rc=$?
[ $rc -eq 1 ] || { echo "cut tape: exit $rc"; exit 1; }
[ ! -e "$d/ray.data" ] || { echo "cut tape left a file"; exit 1; }
exit 0
