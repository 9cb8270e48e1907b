# Sourced by the CLI tests: `need_cmd CMD PACKAGE` ends the test as skipped
# (exit 77, counted by tests/run.sh) when CMD is not on PATH, naming the
# Debian package that provides it.
need_cmd() {
  command -v "$1" >/dev/null 2>&1 && return 0
  echo "skipped: needs $1 (apt-get install -y $2)"
  exit 77
}
# `gl_leaks_not_ours DIR`: under the sanitizer build, leaks inside Mesa's
# libraries (OSMesa, the EGL driver, llvmpipe's LLVM) are not maprt's; the
# suppressions go to DIR/lsan.supp and LSAN_OPTIONS names them.
gl_leaks_not_ours() {
  printf 'leak:libOSMesa.so\nleak:libEGL_mesa.so\nleak:swrast_dri.so\nleak:libLLVM\nleak:libglapi.so\n' > "$1/lsan.supp"
  LSAN_OPTIONS="suppressions=$1/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
  export LSAN_OPTIONS
}
