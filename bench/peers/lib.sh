# Shared by the bench/peers scripts (sourced): timed runs, medians and
# minima. Needs $tmp (a private directory) and $cputime (the timer built
# from bench/peers/cputime.c: microseconds, where /usr/bin/time counts CPU
# in 10 ms steps).

# run LABEL CMD...: one timed run appended to $tmp/LABEL.t as "cpu wall
# user system"
run() {
  label=$1; shift
  "$cputime" "$tmp/$label.t" "$@" || { echo "bench-peers: $label failed: $*" >&2; exit 3; }
}
# med LABEL COL: median of column COL (1 cpu, 2 wall, 3 user, 4 system)
med() { sort -n -k"$2" "$tmp/$1.t" | awk -v c="$2" '{ v[NR] = $c } END { printf "%.3f\n", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# least LABEL COL: minimum of column COL: the run the other jobs of a
# shared machine disturbed least
least() { sort -n -k"$2" "$tmp/$1.t" | awk -v c="$2" 'NR == 1 { printf "%.3f\n", $c }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }
# need_timer: fails unless $cputime can be run
need_timer() { [ -x "$cputime" ] || { echo "bench-peers: timer $cputime is missing (make $cputime)" >&2; exit 3; }; }
