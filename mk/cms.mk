# vm_cms_shim: HET tape blocks are compressed with zlib or bzip2, the two
# libraries Hercules' hetlib uses. libbz2 ships no pkg-config file on Debian,
# so its header is looked for directly.
ifeq ($(shell pkg-config --exists zlib 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += $(shell pkg-config --cflags zlib)
MODULE_LIBS   += $(shell pkg-config --libs zlib)
else
MODULE_LIBS   += -lz
endif
# libbz2 (Debian libbz2-dev) is optional: without it maprt builds, and a
# bzip2 HET block or `--compress bzip2` names the package.
ifeq ($(shell printf '\043include <bzlib.h>\n' | $(CC) -E -x c - -o /dev/null 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DCMS_HAVE_BZIP2
MODULE_LIBS   += -lbz2
endif
