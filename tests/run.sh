#!/bin/sh
# Runs every cmocka binary in BUILD/tests and every CLI script in tests/cli, and
# ends with the "N passed, N failed" line. Exit status 1 if anything failed.
build=${1:-build}
pass=0; fail=0; skip=0; failed_names=""
errf=$(mktemp) || exit 1
trap 'rm -f "$errf"' EXIT
for t in "$build"/tests/test_*; do
  [ -x "$t" ] || continue
  # cmocka writes progress to stdout and its summary to stderr; reading them
  # apart keeps the two from running together on one line.
  out=$("$t" 2>"$errf"); rc=$?
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$errf" | awk '{s+=$1} END {print s+0}')
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$errf" | awk '{s+=$1} END {print s+0}')
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi   # crashed before reporting
  pass=$((pass + p)); fail=$((fail + f))
  if [ "$f" -ne 0 ]; then
    failed_names="$failed_names $(basename "$t")"
    printf '%s\n' "$out" | grep -v '^\[ \(RUN\|       OK\) ' >&2
    cat "$errf" >&2
  fi
  printf '%-40s %4d passed %4d failed\n' "$(basename "$t")" "$p" "$f"
done
for s in tests/cli/*.sh; do
  [ -f "$s" ] || continue
  out=$(MAPRT="$build/maprt" sh "$s" 2>&1); rc=$?
  if [ $rc -eq 0 ]; then
    pass=$((pass + 1)); st=ok
  elif [ $rc -eq 77 ]; then           # skipped: the script says what is missing
    skip=$((skip + 1)); st="skipped ($(printf '%s\n' "$out" | tail -n 1))"
  else
    fail=$((fail + 1)); st=FAILED; failed_names="$failed_names $(basename "$s")"
    printf '%s\n' "$out" >&2
  fi
  printf '%-40s %s\n' "cli/$(basename "$s")" "$st"
done
[ -n "$failed_names" ] && echo "failed:$failed_names"
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
