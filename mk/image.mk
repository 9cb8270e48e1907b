# image: JPEG and TIFF input for compare, each only where pkg-config finds
# the library (Debian libjpeg62-turbo-dev, libtiff-dev); without them maprt
# builds and names the package when handed such a file.
ifeq ($(shell pkg-config --exists libjpeg 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DIMAGE_HAVE_JPEG $(shell pkg-config --cflags libjpeg)
MODULE_LIBS   += $(shell pkg-config --libs libjpeg)
endif
# libtiff is opened with dlopen when a TIFF is read (util/libload): linked,
# it and the seven libraries it brings cost every process 3.9 M instructions
# of relocation at start-up. The name opened is the SONAME of the library
# the headers came with.
ifeq ($(shell pkg-config --exists libtiff-4 2>/dev/null && echo yes),yes)
IMAGE_TIFF_SONAME := $(shell readelf -d $$(pkg-config --variable=libdir libtiff-4)/libtiff.so 2>/dev/null | \
                       sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
$(BUILD)/obj/src/image/image_tiff.o: MODULE_CFLAGS += -DIMAGE_HAVE_TIFF $(shell pkg-config --cflags libtiff-4) \
  -DIMAGE_TIFF_SONAME='"$(or $(IMAGE_TIFF_SONAME),libtiff.so)"'
endif
