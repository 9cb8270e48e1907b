#!/bin/sh
# Runs every cmocka binary in BUILD/tests and every CLI script in tests/cli, and
# ends with the "N passed, N failed, N skipped" line. A test that cannot run
# here (a package is missing) is skipped and counted, with the reason: a cmocka
# case that calls skip(), a unit test not built (no cmocka), or a CLI script
# that exits 77 (as under automake) after printing why. Exit status 1 if
# anything failed, or if anything was skipped and MAPRT_NO_SKIP is set (CI).
build=${1:-build}
pass=0; fail=0; skip=0; failed_names=""; skipped_names=""
errf=$(mktemp) || exit 1
trap 'rm -f "$errf"' EXIT
for src in tests/unit/test_*.c; do
  n=$(basename "$src" .c); t="$build/tests/$n"
  if [ ! -x "$t" ]; then
    # Only a missing cmocka leaves a unit test unbuilt (see the Makefile).
    skip=$((skip + 1)); skipped_names="$skipped_names $n"
    printf '%-40s skipped: needs libcmocka-dev (apt-get install -y libcmocka-dev)\n' "$n"
    continue
  fi
  # cmocka writes progress to stdout and its summary to stderr; reading them
  # apart keeps the two from running together on one line.
  out=$("$t" 2>"$errf"); rc=$?
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$errf" | awk '{s+=$1} END {print s+0}')
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$errf" | awk '{s+=$1} END {print s+0}')
  k=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$errf" | awk '{s+=$1} END {print s+0}')
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi   # crashed before reporting
  pass=$((pass + p)); fail=$((fail + f)); skip=$((skip + k))
  if [ "$f" -ne 0 ]; then
    failed_names="$failed_names $n"
    printf '%s\n' "$out" | grep -v '^\[ \(RUN\|       OK\) ' >&2
    cat "$errf" >&2
  fi
  if [ "$k" -ne 0 ]; then
    skipped_names="$skipped_names $n"
    # the reasons: the "# skipped: ..." lines the cases print before skip()
    printf '%s\n' "$out" | sed -n 's/^# \(skipped: .*\)/  \1/p' | sort -u
  fi
  printf '%-40s %4d passed %4d failed %4d skipped\n' "$n" "$p" "$f" "$k"
done
for s in tests/cli/*.sh; do
  [ -f "$s" ] || continue
  out=$(MAPRT="$build/maprt" sh "$s" 2>&1); rc=$?
  case $rc in
    0)  pass=$((pass + 1)); st=ok ;;
    77) skip=$((skip + 1)); skipped_names="$skipped_names $(basename "$s")"
        st="skipped: $(printf '%s\n' "$out" | sed -n 's/^skipped: //p' | tail -1)" ;;
    *)  fail=$((fail + 1)); st=FAILED; failed_names="$failed_names $(basename "$s")"
        printf '%s\n' "$out" >&2 ;;
  esac
  printf '%-40s %s\n' "cli/$(basename "$s")" "$st"
done
[ -n "$failed_names" ] && echo "failed:$failed_names"
[ -n "$skipped_names" ] && echo "skipped:$skipped_names (sh tools/deps.sh test lists what is missing)"
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ] || exit 1
if [ "$skip" -ne 0 ] && [ -n "${MAPRT_NO_SKIP:-}" ]; then
  echo "MAPRT_NO_SKIP is set: nothing may be skipped" >&2
  exit 1
fi
exit 0
