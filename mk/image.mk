# image: JPEG and TIFF input for compare, each only where pkg-config finds
# the library (Debian libjpeg62-turbo-dev, libtiff-dev); without them maprt
# builds and names the package when handed such a file.
ifeq ($(shell pkg-config --exists libjpeg 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DIMAGE_HAVE_JPEG $(shell pkg-config --cflags libjpeg)
MODULE_LIBS   += $(shell pkg-config --libs libjpeg)
endif
ifeq ($(shell pkg-config --exists libtiff-4 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DIMAGE_HAVE_TIFF $(shell pkg-config --cflags libtiff-4)
MODULE_LIBS   += $(shell pkg-config --libs libtiff-4)
endif
