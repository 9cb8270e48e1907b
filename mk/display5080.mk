# display5080: the OpenGL backends, each only where pkg-config finds it.
# OSMesa left Mesa in 25.1, so its absence is normal; EGL is the path forward.
ifeq ($(shell pkg-config --exists osmesa 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DDL_HAVE_OSMESA $(shell pkg-config --cflags osmesa)
MODULE_LIBS   += $(shell pkg-config --libs osmesa)
endif
ifeq ($(shell pkg-config --exists egl 2>/dev/null && echo yes),yes)
MODULE_CFLAGS += -DDL_HAVE_EGL $(shell pkg-config --cflags egl)
MODULE_LIBS   += $(shell pkg-config --libs egl)
endif
