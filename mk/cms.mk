# vm_cms_shim: HET tape blocks are compressed with zlib or bzip2, the two
# libraries Hercules' hetlib uses. libbz2 ships no pkg-config file on Debian.
ifeq ($(shell pkg-config --exists zlib 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += $(shell pkg-config --cflags zlib)
MODULE_LIBS   += $(shell pkg-config --libs zlib)
else
MODULE_LIBS   += -lz
endif
MODULE_LIBS   += -lbz2
