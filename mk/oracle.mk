# The Fortran REAL(16) geometry oracle used by test_oracle (tests/oracle/).
# make's built-in FC is f77; prefer gfortran unless FC was set by the user.
ifeq ($(origin FC),default)
FC := gfortran
endif
FFLAGS ?= -O2
ORACLE := $(BUILD)/oracle/geom_oracle
TEST_EXTRA += $(ORACLE)

$(ORACLE): tests/oracle/geom_oracle.f90
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -J $(@D) -o $@ $<
