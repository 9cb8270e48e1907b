# The 5081 colour-table bench (bench/quant_bench.c): maprt's median cut
# against libimagequant (Debian libimagequant-dev), `make quant-bench
# QUANT_IN=picture.png`; figures in docs/dl5080.md.
QUANT_BENCH := $(BUILD)/quant_bench
QUANT_IN ?= out/fig1.png

$(QUANT_BENCH): bench/quant_bench.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) $(shell pkg-config --cflags imagequant) $(LDFLAGS) -o $@ $< $(LIB) \
	  $(LIBS) $(shell pkg-config --libs imagequant 2>/dev/null || echo -limagequant)

.PHONY: quant-bench
quant-bench: $(QUANT_BENCH)
	$(QUANT_BENCH) $(QUANT_IN)
