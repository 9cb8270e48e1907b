# The Fortran REAL(16) oracles (tests/oracle/): spans of single primitives
# for test_oracle, primary rays of whole scenes for test_ids and bench.
# make's built-in FC is f77; prefer gfortran unless FC was set by the user.
ifeq ($(origin FC),default)
FC := gfortran
endif
FFLAGS ?= -O2
ORACLE := $(BUILD)/oracle/geom_oracle
IDS_ORACLE := $(BUILD)/oracle/ids_oracle
# Built only where the Fortran compiler is; the oracle tests skip (counted) else.
ifneq ($(shell command -v $(FC) 2>/dev/null),)
TEST_EXTRA += $(ORACLE) $(IDS_ORACLE)
endif

ORACLE_MATH := $(BUILD)/oracle/oracle_math.o

$(ORACLE_MATH): tests/oracle/oracle_math.f90
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -J $(@D) -c -o $@ $<

$(ORACLE): tests/oracle/geom_oracle.f90 $(ORACLE_MATH)
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -J $(@D) -o $@ $< $(ORACLE_MATH)

# The primary-ray tracer in REAL(16) behind `render --ids` checks and
# `maprt bench --oracle` (docs/idmap.md).
$(IDS_ORACLE): tests/oracle/ids_oracle.f90 $(ORACLE_MATH)
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -J $(@D) -o $@ $< $(ORACLE_MATH)
bench: $(IDS_ORACLE)
