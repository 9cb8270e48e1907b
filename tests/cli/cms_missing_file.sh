#!/bin/sh
# A missing CMS file: RC 28 in the message, exit status 1; a disk that is not
# accessed: RC 36; a bad fileid: RC 20 / 24.
set -u
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
out=$("$MAPRT" cms type 'NOPE DATA A' --disk A="$d" 2>&1); rc=$?
[ $rc -eq 1 ] || { echo "exit $rc, expected 1"; exit 1; }
[ "$out" = "maprt: NOPE DATA A1: error: file not found (RC 28)" ] || { echo "got: $out"; exit 1; }
out=$("$MAPRT" cms type 'NOPE DATA Z' 2>&1); rc=$?
[ $rc -eq 1 ] || { echo "exit $rc, expected 1"; exit 1; }
[ "$out" = "maprt: NOPE DATA Z1: error: disk not accessed (RC 36): no directory for disk Z (use --disk Z=DIR or MAPRT_DISK_Z)" ] || { echo "got: $out"; exit 1; }
out=$(MAPRT_DISK_Z="$d" "$MAPRT" cms type 'NOPE DATA Z' 2>&1); rc=$?
[ $rc -eq 1 ] && echo "$out" | grep -q 'RC 28' || { echo "env disk: $rc $out"; exit 1; }
out=$("$MAPRT" cms type 'NOPE DATA A9' 2>&1); rc=$?
[ $rc -eq 1 ] || { echo "exit $rc, expected 1"; exit 1; }
[ "$out" = "maprt: NOPE DATA A9: error: invalid filemode (RC 24): 'A9' is not a letter A-Z with an optional number 0-6" ] || { echo "got: $out"; exit 1; }
out=$("$MAPRT" cms type 'NOPE DA.TA' 2>&1); rc=$?
[ $rc -eq 1 ] && echo "$out" | grep -q '(RC 20)' || { echo "RC 20: $rc $out"; exit 1; }
exit 0
