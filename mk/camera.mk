# The primary rays' set-up (cscene_primary_batch in src/trace/cscene.c) is
# a set of loops over lanes that GCC vectorises only when a square root
# need not set errno and a comparison or division may be computed for a
# lane whose result is then not selected (no code here reads errno after
# a math call or tests floating-point flags); the values are IEEE's
# either way, so the pictures do not change (docs/performance.md).
$(foreach m,$(MODE_DIRS),$(BUILD)/$(m)/src/trace/cscene.o): MODULE_CFLAGS += -fno-math-errno -fno-trapping-math
