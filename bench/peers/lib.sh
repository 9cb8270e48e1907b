# Shared by the bench/peers scripts (sourced): timed runs and medians.
# Needs $tmp (a private directory).

# run LABEL CMD...: one timed run appended to $tmp/LABEL.t as "cpu wall"
run() {
  label=$1; shift
  /usr/bin/time -f "%U %S %e" -o "$tmp/time" "$@" >/dev/null 2>&1 || { echo "bench-peers: $label failed: $*" >&2; exit 3; }
  awk '{ printf "%.3f %.3f\n", $1 + $2, $3 }' "$tmp/time" >> "$tmp/$label.t"
}
# med LABEL COL: median of column COL (1 cpu, 2 wall)
med() { sort -n -k"$2" "$tmp/$1.t" | awk -v c="$2" '{ v[NR] = $c } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }
