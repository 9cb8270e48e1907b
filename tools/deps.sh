#!/bin/sh
# The Debian packages maprt uses, grouped by what needs them.
#
#   sh tools/deps.sh demo   checks what `make demo` / `make all` need
#   sh tools/deps.sh test   ... and what the tests use; tests whose package is
#                           missing are skipped and counted (tests/run.sh)
#   sh tools/deps.sh fuzz   ... and what `make fuzz-smoke` needs
#   sh tools/deps.sh bench  ... and what the optional benches need
#   sh tools/deps.sh all    every package (CI: nothing may be skipped)
#   sh tools/deps.sh list [GROUP]  prints the table
#
# Run as root, it installs what is missing with apt-get. Otherwise a missing
# package of a needed group prints the exact apt-get line and fails, and a
# missing optional one (the test group for `test`) prints it as a note only.
#
# The table: one package a line, "GROUP PACKAGE what needs it". Add a line
# for a new package; GROUP is demo, test, bench or fuzz.
DEPS_TABLE='
demo gcc                 the C99 compiler, with OpenMP
demo make                the build
demo pkg-config          finds zlib, Open MPI, libjpeg and libtiff
demo libpng-dev          PNG input and output
demo libdeflate-dev      the threaded PNG encoder (its deflate)
demo zlib1g-dev          the PNG encoder (zlib stream, Adler-32) and HET tapes (zlib blocks)
test libcmocka-dev       the unit tests (tests/unit)
test libbz2-dev          HET tapes with bzip2 blocks (vm_cms_shim; without it maprt names the package)
test gfortran            the REAL(16) geometry oracle (test_oracle)
test libosmesa6-dev      dl2png --backend osmesa and its tests
test libegl-dev          dl2png --backend egl and its tests
test libgl-dev           OpenGL for both GL backends
test libgles-dev         OpenGL ES headers for the EGL backend
test libgl1-mesa-dri     Mesa software rasteriser for the GL backends
test libegl-mesa0        Mesa EGL driver (surfaceless context)
test gnuplot-nox         bench --plot (tests/cli/bench_plot.sh)
test libjpeg62-turbo-dev compare reads JPEG (mk/image.mk)
test libtiff-dev         compare reads TIFF (mk/image.mk)
test imagemagick         writes the JPEG/TIFF test pictures (tests/cli/compare_formats.sh)
test strace              tests/cli/threads.sh counts the threads a render starts
test hercules            tapemap, hetmap, hetupd (cms tests) and the HFP instructions (test_hfp)
test libopenmpi-dev      the MPI build (mk/mpi.mk) and tests/cli/mpi.sh
test openmpi-bin         mpirun for tests/cli/mpi.sh
bench povray             make bench-peers (POV-Ray 3.7)
bench time               /usr/bin/time in bench/fig1.sh and make bench-peers
bench libimagequant-dev  the colour-table bench against median cut (make quant-bench)
fuzz clang               libFuzzer targets (make fuzz-smoke)
fuzz libclang-rt-14-dev  libFuzzer and sanitizer runtimes for clang
fuzz libomp-dev          OpenMP for the clang builds
'

deps_group() {   # the packages of group $1
  printf '%s\n' "$DEPS_TABLE" | awk -v g="$1" '$1 == g { print $2 }'
}

deps_missing() {   # the uninstalled ones among $@
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || printf ' %s' "$p"
  done
}

deps_install() {   # installs $@ as root; 0 ok
  echo "deps: installing $*"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends "$@" >/dev/null && return 0
  echo "deps: apt-get failed; run: apt-get install -y $*" >&2
  return 1
}

what=${1:-test}
case $what in
  demo) need=demo; want= ;;
  test) need=demo; want=test ;;
  fuzz) need="demo fuzz"; want= ;;
  bench) need="demo bench"; want= ;;
  all)  need="demo test bench fuzz"; want= ;;
  list) printf '%s\n' "$DEPS_TABLE" | awk -v g="${2:-}" 'NF && (g == "" || $1 == g)'; exit 0 ;;
  *) echo "usage: sh tools/deps.sh demo|test|bench|fuzz|all|list [GROUP]" >&2; exit 2 ;;
esac
need_pkgs=$(for g in $need; do deps_group "$g"; done)
want_pkgs=$(for g in $want; do deps_group "$g"; done)
if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "deps: not a Debian system; the equivalents of these are used:" $need_pkgs $want_pkgs >&2
  exit 0
fi
# shellcheck disable=SC2086
missing=$(deps_missing $need_pkgs)
# shellcheck disable=SC2086
optional=$(deps_missing $want_pkgs)
[ -z "$missing$optional" ] && exit 0
if [ "$(id -u)" = 0 ]; then
  # shellcheck disable=SC2086
  deps_install $missing $optional || { [ -z "$missing" ] || exit 1; }
  exit 0
fi
if [ -n "$optional" ]; then
  echo "deps: optional packages missing; the tests that use them will be skipped:" >&2
  for p in $optional; do
    printf '%s\n' "$DEPS_TABLE" | awk -v p="$p" '$2 == p { $1 = ""; sub(/^ +/, ""); sub(/ +/, "  "); print "  " $0 }' >&2
  done
  echo "  to run them, as root: apt-get install -y$optional" >&2
fi
if [ -n "$missing" ]; then
  echo "deps: missing packages that 'make $what' needs; run as root:" >&2
  echo "  apt-get install -y$missing" >&2
  exit 1
fi
exit 0
