# PDS lookup-rate bench (bench/pds_bench.c): `make pds-bench`.
PDS_BENCH := $(BUILD)/pds_bench

$(PDS_BENCH): bench/pds_bench.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LIBS)

.PHONY: pds-bench
pds-bench: $(PDS_BENCH)
	$(PDS_BENCH) $(PDS_BENCH_ARGS)
