#!/bin/sh
# maprt hfp: HFP register images to and from IEEE doubles, and its errors.
set -u
fail() { echo "hfp.sh: $*" >&2; exit 1; }

$MAPRT hfp --help | grep -q 'maprt hfp decode HEX' || fail "--help"
# -118.625 = -0.76A x 16^2 (the usual example); 1.0; the short 0.1 rounded by LRER.
[ "$($MAPRT hfp decode C276A000 4110000000000000)" = "$(printf -- '-118.625\n1')" ] || fail "decode"
[ "$($MAPRT hfp encode short 0.1 -118.625)" = "$(printf '4019999A\nC276A000')" ] || fail "encode short"
[ "$($MAPRT hfp encode long 0.1)" = "401999999999999A" ] || fail "encode long"
# The range ends: (1 - 16^-6) x 16^63 and 16^-65.
[ "$($MAPRT hfp decode 7fffffff 00100000)" = "$(printf '7.2370051459731155e+75\n5.3976053469340279e-79')" ] \
  || fail "range ends"
err=$($MAPRT hfp encode short 1e76 2>&1 >/dev/null); [ $? -eq 1 ] || fail "1e76 should exit 1"
[ "$err" = "maprt: 1e76: error: 1e+76 is above the largest HFP short number (about 7.2e75)" ] || fail "1e76 message: $err"
$MAPRT hfp decode C276A0 2> /dev/null; [ $? -eq 2 ] || fail "6 digits should exit 2"
$MAPRT hfp encode medium 1 2> /dev/null; [ $? -eq 2 ] || fail "bad width should exit 2"
$MAPRT hfp encode short x 2> /dev/null; [ $? -eq 2 ] || fail "bad number should exit 2"
$MAPRT hfp 2> /dev/null; [ $? -eq 2 ] || fail "no verb should exit 2"
exit 0
