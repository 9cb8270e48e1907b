#!/bin/sh
# maprt's tapes against Hercules' own tape utilities, and a real VM/370 tape:
# - tests/data/vm370-cms-cp-help.het (a real VMFPLC2 tape, see tests/data/README.md)
#   decompressed by hetupd gives the original AWS image; both import identically;
# - every tape maprt writes (VMFPLC2 and TAPE DUMP, AWS, HET zlib and bzip2) maps
#   cleanly with tapemap and hetmap;
# - tapes hetupd converts (AWS -> HET zlib, HET bzip2, back to AWS) import to the
#   same files, byte for byte, binary files and sidecars included.
# Needs the Hercules utilities (Debian package hercules); without them it says
# SKIP and why.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
imp() {   # imp TAPE DIR: import TAPE into a fresh DIR
  rm -rf "$2"; mkdir "$2"
  "$MAPRT" cms import "$1" --disk A="$2" > "$2.log" 2>&1 || fail "import $1: $(cat "$2.log")"
}

# a build without libbz2 (Debian libbz2-dev) refuses bzip2 with the package
# named; the bzip2 forms below are then left out
mkdir "$d/empty"
bz2=het-bzip2
msg=$("$MAPRT" cms export "X Y A" "$d/x.het" --form het --compress bzip2 --disk A="$d/empty" 2>&1)
case "$msg" in
  *"built without libbz2 (apt-get install libbz2-dev"*) bz2= ;;
esac

# Hercules' own HET tapes (zlib, bzip2): labelled and empty; read, labels noted.
# This part needs no Hercules tool.
for h in tests/data/hercules-hetbsf-zlib.het tests/data/hercules-hetbsf-bzip2.het; do
  rm -rf "$d/e"; mkdir "$d/e"
  msg=$("$MAPRT" cms import "$h" --disk A="$d/e" 2>&1); rc=$?
  [ $rc -eq 1 ] || fail "$h: exit $rc"
  case "$h,$bz2,$msg" in
    *bzip2.het,,*"offset 0: error: HET record is compressed with bzip2, and this maprt was built without libbz2"*) ;;
    *,*"offset 0: warning: standard label skipped: VOL1000000"*"error: no CMS files found"*) ;;
    *) fail "$h: $msg" ;;
  esac
done

. tests/need.sh
for t in tapemap hetmap hetupd; do
  need_cmd $t hercules
done

# the real tape: HET -> AWS by Hercules, both import to the same 46 files
hetupd -d tests/data/vm370-cms-cp-help.het "$d/help.aws" >/dev/null 2>&1 || fail "hetupd -d"
sum=$(sha256sum < "$d/help.aws" | cut -c1-64)
[ "$sum" = 849aaa6a67db98a22789e28c6050641628c0f395d15af5fe3fcc01fa5fc9bc69 ] || fail "help.aws sha256 $sum"
imp tests/data/vm370-cms-cp-help.het "$d/h1"
imp "$d/help.aws" "$d/h2"
diff -r "$d/h1" "$d/h2" >/dev/null || fail "HET and AWS forms of the real tape import differently"
grep -q '^46 files imported to disk A$' "$d/h1.log" || fail "real tape: $(tail -1 "$d/h1.log")"
grep -q '^WATFIV HELPCMD A2    F    80       18 records  (vmfplc2, code page 1047, 2022-01-07 19:57:00)$' \
  "$d/h1.log" || fail "real tape: WATFIV HELPCMD line"
[ "$(grep -c 'binary' "$d/h1.log")" -eq 0 ] || fail "real tape: a file read as binary"

# a broken previous-length chain: tapemap reads the tape anyway, and so does
# maprt, with one warning naming the offset (the second block's header)
cp "$d/help.aws" "$d/broken.aws"
printf '\377' | dd of="$d/broken.aws" bs=1 seek=$((6 + 77 + 2)) conv=notrunc 2>/dev/null
tapemap "$d/broken.aws" > "$d/map" 2>&1 || fail "tapemap refuses the broken chain"
rm -rf "$d/b"; mkdir "$d/b"
"$MAPRT" cms import "$d/broken.aws" --disk A="$d/b" > "$d/b.log" 2> "$d/b.err" || fail "broken chain: $(cat "$d/b.err")"
grep -q '^46 files imported' "$d/b.log" || fail "broken chain: $(tail -1 "$d/b.log")"
grep -q "broken.aws: offset 83: warning: AWS header: previous length" "$d/b.err" || fail "no warning: $(cat "$d/b.err")"
diff -r "$d/h1" "$d/b" >/dev/null || fail "broken chain imports differently"

# an import never replaces its own input: a tape named like a CMS file on the disk
mkdir "$d/self"
cp tests/fuzz/seeds/fuzz_cms_tape/vmfplc2 "$d/self/plcf.data"
"$MAPRT" cms import "$d/self/plcf.data" --disk A="$d/self" --replace > "$d/self.log" 2>&1; rc=$?
[ $rc -eq 1 ] || fail "importing over the input: exit $rc"
grep -q "would replace the input" "$d/self.log" || fail "self import: $(cat "$d/self.log")"
cmp -s tests/fuzz/seeds/fuzz_cms_tape/vmfplc2 "$d/self/plcf.data" || fail "the input was changed"

# a disk with a binary file (the seed tape's hole) next to the help files
cp "$d"/h1/* "$d/h2/" 2>/dev/null
"$MAPRT" cms import tests/fuzz/seeds/fuzz_cms_tape/dump --disk A="$d/h2" >/dev/null || fail "seed import"
names=$(cd "$d/h2" && ls | grep -v '\.cms$' | tr 'a-z' 'A-Z' | sed "s/^\(.*\)\.\(.*\)$/\1 \2 A/")
ok=1
for fmt in vmfplc2 dump; do
  for form in aws het-zlib $bz2; do
    out="$d/out-$fmt-$form.tape"
    case $form in
      aws) set -- --form aws ;;
      het-zlib) set -- --form het --compress zlib ;;
      het-bzip2) set -- --form het --compress bzip2 ;;
    esac
    echo "$names" | sed "s/.*/'&'/" | tr '\n' ' ' > "$d/args"
    eval "\"\$MAPRT\" cms export $(cat "$d/args") \"\$out\" \"\$@\" --tape-format $fmt --disk A=\"\$d/h2\"" ||
      fail "export $fmt $form"
    tapemap "$out" > "$d/map" 2>&1 || fail "tapemap $fmt $form: $(tail -3 "$d/map")"
    hetmap "$out" > "$d/hmap" 2>&1 || fail "hetmap $fmt $form: $(tail -3 "$d/hmap")"
    grep -q 'Error\|error' "$d/hmap" && fail "hetmap reports an error for $fmt $form"
    imp "$out" "$d/r"
    # the records round-trip byte for byte; a TAPE DUMP trailer keeps no seconds
    for f in "$d"/h2/*; do
      b=$(basename "$f")
      case $b in
        *.cms) [ $fmt = dump ] && continue ;;
      esac
      cmp -s "$f" "$d/r/$b" || { echo "differs after $fmt $form: $b"; ok=0; }
    done
    # Hercules converts the tape; the copy imports to the same files
    for conv in "-z" ${bz2:+"-b"} "-d"; do
      hetupd $conv "$out" "$d/conv.het" >/dev/null 2>&1 || fail "hetupd $conv of $fmt $form"
      imp "$d/conv.het" "$d/c"
      diff -r "$d/r" "$d/c" >/dev/null || fail "hetupd $conv copy of $fmt $form imports differently"
    done
  done
done
[ $ok -eq 1 ] || fail "round trips not byte-exact"
exit 0
