# Sourced by the CLI tests: `need_cmd CMD PACKAGE` ends the test as skipped
# (exit 77, counted by tests/run.sh) when CMD is not on PATH, naming the
# Debian package that provides it.
need_cmd() {
  command -v "$1" >/dev/null 2>&1 && return 0
  echo "skipped: needs $1 (apt-get install -y $2)"
  exit 77
}
