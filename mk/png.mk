# The PNG row filters (src/image/image_png_write.c) are byte loops that GCC
# vectorises only at -O3 (its dynamic cost model; -O2 keeps them scalar):
# a third fewer instructions in the filters, the same bytes out
# (docs/performance.md).
$(BUILD)/obj/src/image/image_png_write.o: MODULE_CFLAGS += -O3
