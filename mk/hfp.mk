# The full check of the System/370 HFP arithmetic (docs/numerics.md):
# 1,000,000 random operands per operation against the 128-bit reference,
# and per instruction against Hercules.
.PHONY: hfp-check
hfp-check: $(BUILD)/tests/test_hfp $(BUILD)/tests/test_hfp_hercules
	MAPRT_HFP_N=1000000 $(BUILD)/tests/test_hfp
	MAPRT_HFP_HERC_N=1000000 $(BUILD)/tests/test_hfp_hercules
