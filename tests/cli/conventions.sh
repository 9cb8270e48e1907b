#!/bin/sh
# getopt_long conventions for every subcommand: --opt=value, '--', --version,
# enum values in any case, "did you mean" for options and commands, and a
# host file that exists winning over a fileid reading of its name.
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
case $MAPRT in /*) ;; *) MAPRT=$PWD/$MAPRT ;; esac
fail() { echo "conventions.sh: $*" >&2; exit 1; }

v=$($MAPRT --version) || fail "--version should exit 0"
echo "$v" | grep -q '^maprt [0-9][0-9.]*' || fail "--version prints '$v'"
[ "$($MAPRT render --version)" = "$v" ] || fail "render --version differs"
[ "$($MAPRT cms --version)" = "$v" ] || fail "cms --version differs"

$MAPRT render scenes/csg.scene --size=16x12 --numeric=Q32 --aa=2 -o "$tmp/a.png" --stats > "$tmp/s" \
  || fail "--opt=value and Q32 refused"
grep -qx 'numeric=q32' "$tmp/s" && grep -qx 'rays.primary=768' "$tmp/s" || fail "--size=16x12 --aa=2 not applied"
$MAPRT compare "$tmp/a.png" "$tmp/a.png" --threshold=4 | grep -qx 'threshold=4' || fail "compare --threshold=4"
$MAPRT dl2png --backend=PNG 2>&1 | grep -q "needs IN.dl5080" || fail "--backend=PNG refused"

# '--' ends the options: a deck named '-x.scene'
cp scenes/csg.scene "$tmp/-x.scene"
(cd "$tmp" && $MAPRT render -o b.png --size 8x8 -- -x.scene) || fail "'--' then -x.scene"
[ -s "$tmp/b.png" ] || fail "no output after '--'"

# did you mean
$MAPRT render scenes/csg.scene --szie 8x8 -o "$tmp/c.png" 2> "$tmp/err"; [ $? -eq 2 ] || fail "unknown option should exit 2"
grep -q "unknown option '--szie' (did you mean --size?)" "$tmp/err" || fail "render: $(cat "$tmp/err")"
$MAPRT compare a b --regster 2> "$tmp/err"; grep -q "(did you mean --register?)" "$tmp/err" || fail "compare: $(cat "$tmp/err")"
$MAPRT cms list --dsk A=. 2> "$tmp/err"; grep -q "(did you mean --disk?)" "$tmp/err" || fail "cms: $(cat "$tmp/err")"
$MAPRT render scenes/csg.scene --zzzzzz 2> "$tmp/err"; grep -qx "maprt render: error: unknown option '--zzzzzz'" "$tmp/err" \
  || fail "no suggestion expected: $(cat "$tmp/err")"
$MAPRT rendr 2> "$tmp/err"; [ $? -eq 2 ] && grep -q "unknown command 'rendr' (did you mean render?)" "$tmp/err" \
  || fail "command: $(cat "$tmp/err")"

# a host file 'my deck' exists: it is read, not 'MY DECK A1'
cp scenes/csg.scene "$tmp/my deck"
(cd "$tmp" && $MAPRT render "my deck" -o d.png --size 8x8) || fail "host file 'my deck' not read"
# and without it the name is a fileid (CMS RC 28)
(cd "$tmp" && $MAPRT render "no deck" -o d.png --size 8x8) 2> "$tmp/err"; [ $? -eq 1 ] || fail "missing fileid should exit 1"
grep -q "NO DECK A1: error: file not found (RC 28)" "$tmp/err" || fail "RC 28: $(cat "$tmp/err")"
exit 0
