# The Fortran REAL(16) geometry oracle used by test_oracle (tests/oracle/).
# make's built-in FC is f77; prefer gfortran unless FC was set by the user.
ifeq ($(origin FC),default)
FC := gfortran
endif
FFLAGS ?= -O2
ORACLE := $(BUILD)/oracle/geom_oracle
# Built only where the Fortran compiler is; test_oracle skips (counted) else.
ifneq ($(shell command -v $(FC) 2>/dev/null),)
TEST_EXTRA += $(ORACLE)
endif

$(ORACLE): tests/oracle/geom_oracle.f90
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -J $(@D) -o $@ $<
