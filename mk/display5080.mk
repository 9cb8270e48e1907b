# display5080: the OpenGL backends load libOSMesa and libEGL with dlopen
# when chosen (display5080/dl_lib.c), so nothing here links them; glibc
# before 2.34 keeps dlopen in libdl.
MODULE_LIBS += -ldl
