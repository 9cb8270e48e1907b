# maprt — GNU make build. Overridable: CC FC CFLAGS LDFLAGS PREFIX DESTDIR.
# Sources are discovered by directory, so a new module is a new .c file, and
# module-specific flags live in mk/*.mk fragments.
CC      ?= cc
FC      ?= gfortran
PREFIX  ?= /usr/local
DESTDIR ?=
CFLAGS  ?= -O3 -g
LDFLAGS ?=
BUILD   ?= build

WARN     := -std=c99 -pedantic -Wall -Wextra -Werror
CPPFLAGS += -D_POSIX_C_SOURCE=200809L -Isrc -I. -MMD -MP
ALL_CFLAGS = $(WARN) $(CFLAGS) -fopenmp $(MODULE_CFLAGS)
# -ldl: util/libload's dlopen (glibc before 2.34 keeps it in libdl)
LIBS     = $(MODULE_LIBS) -lpng -ldeflate -lz -lm -ldl
MODES    := q16 q32 f32 f64 hfp32 hfp64

# Directories compiled once per numeric mode (symbols prefixed by mode).
MODAL_DIRS  := src/geom src/pds src/trace
MODAL_SRC   := $(foreach d,$(MODAL_DIRS),$(wildcard $(d)/*.c))
COMMON_SRC  := $(filter-out src/cli/main.c $(MODAL_SRC),\
                 $(wildcard src/*/*.c vm_cms_shim/*.c display5080/*.c))
COMMON_OBJ  := $(COMMON_SRC:%.c=$(BUILD)/obj/%.o)
# x86-64 with GCC 12 or later: each mode's tracer is compiled a second time
# for x86-64-v3 (AVX2, BMI2, FMA: symbols q16_v3_..., objects in
# BUILD/q16-v3), and render_ops_find takes it where the processor has that
# level (__builtin_cpu_supports, which Clang 14 cannot ask). a*b+c must
# stay two roundings, not one FMA: -std=c99 already keeps GCC from fusing
# them, -ffp-contract=off says so where it matters (fused, the glass
# scene's f32 picture changes). Both builds draw the same pictures, bit
# for bit (tests/cli/isa.sh). `make ISA_V3=` builds the baseline alone.
ifeq ($(origin ISA_V3),undefined)
ISA_V3 := $(shell printf 'int main(void) { return !__builtin_cpu_supports("x86-64-v3"); }\n' \
            | $(CC) -march=x86-64-v3 -x c - -fsyntax-only 2>/dev/null && echo yes)
endif
V3_CFLAGS   := -march=x86-64-v3 -ffp-contract=off
MODE_DIRS   := $(MODES) $(if $(ISA_V3),$(MODES:%=%-v3))
MODAL_OBJ   := $(foreach m,$(MODE_DIRS),$(MODAL_SRC:%.c=$(BUILD)/$(m)/%.o))
LIB         := $(BUILD)/libmaprt.a
BIN         := $(BUILD)/maprt

TEST_SRC    := $(wildcard tests/unit/test_*.c)
TEST_BIN    := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)
# The unit tests need cmocka; without it `make test` runs the rest and
# tests/run.sh counts the unit tests as skipped. `make HAVE_CMOCKA=` pretends.
HAVE_CMOCKA ?= $(shell printf '\043include <stdarg.h>\n\043include <stddef.h>\n\043include <setjmp.h>\n\043include <cmocka.h>\n' \
                 | $(CC) -E -x c - -o /dev/null 2>/dev/null && echo yes)

MODULE_CFLAGS :=
MODULE_LIBS   :=
# Fragments may define rules; `all` stays the default goal.
.DEFAULT_GOAL := all
-include mk/*.mk

quant-bench: deps-bench
.PHONY: all test demo bench install uninstall clean deps deps-demo deps-test deps-bench deps-fuzz unit-tests asan-test fuzz-smoke fuzz check-deps
all: $(BIN)

# --- packages --------------------------------------------------------------
# tools/deps.sh groups the packages by what needs them: `make demo` checks
# only the demo group, `make test` also notes (or as root installs) what the
# tests use, and `make deps` checks (or installs) everything.
deps:
	@sh tools/deps.sh all
# (explicit, not a pattern rule: make does not search patterns for .PHONY targets)
deps-demo deps-test deps-bench deps-fuzz:
	@sh tools/deps.sh $(@:deps-%=%)

# --- compile ---------------------------------------------------------------
# Objects depend on the flags they are built with, so that a package found
# later by pkg-config (e.g. OSMesa installed by `make deps`) rebuilds them.
FLAGS_STAMP := $(BUILD)/flags.stamp
FLAGS_NOW = $(CC) $(CPPFLAGS) $(ALL_CFLAGS) $(LDFLAGS) $(LIBS) $(if $(ISA_V3),$(V3_CFLAGS))
.PHONY: FORCE
FORCE:
$(FLAGS_STAMP): FORCE
	@mkdir -p $(@D)
	@echo '$(FLAGS_NOW)' | cmp -s - $@ || echo '$(FLAGS_NOW)' > $@

# Build facts compiled into one object each, rebuilt when they change: the
# git revision (version.o: --version, provenance) and where the shipped
# scenes are (cli_data.o: PREFIX/share/maprt after install, else this tree).
GIT_REV := $(shell git describe --always --dirty 2>/dev/null)
DATADIR := $(PREFIX)/share/maprt
INFO_NOW = $(GIT_REV) $(DATADIR) $(CURDIR)
INFO_STAMP := $(BUILD)/info.stamp
$(INFO_STAMP): FORCE
	@mkdir -p $(@D)
	@echo '$(INFO_NOW)' | cmp -s - $@ || echo '$(INFO_NOW)' > $@
$(BUILD)/obj/src/util/version.o $(BUILD)/obj/src/cli/cli_data.o: $(INFO_STAMP)
$(BUILD)/obj/src/util/version.o: MODULE_CFLAGS += $(if $(GIT_REV),-DMAPRT_REV='"$(GIT_REV)"')
$(BUILD)/obj/src/cli/cli_data.o: MODULE_CFLAGS += -DMAPRT_DATADIR='"$(DATADIR)"' -DMAPRT_SRCDIR='"$(CURDIR)"'

$(BUILD)/obj/%.o: %.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@

define MODE_RULE
$(BUILD)/$(1)/%.o: %.c $(FLAGS_STAMP)
	@mkdir -p $$(@D)
	$$(CC) $$(CPPFLAGS) -DNUM_MODE=$(1) -DNUM_MODE_$(1) $$(ALL_CFLAGS) -c $$< -o $$@
endef
$(foreach m,$(MODES),$(eval $(call MODE_RULE,$(m))))

define MODE_V3_RULE
$(BUILD)/$(1)-v3/%.o: %.c $(FLAGS_STAMP)
	@mkdir -p $$(@D)
	$$(CC) $$(CPPFLAGS) -DNUM_MODE=$(1) -DNUM_MODE_$(1) -DNUM_ISA_V3 $$(ALL_CFLAGS) $(V3_CFLAGS) -c $$< -o $$@
endef
$(if $(ISA_V3),$(foreach m,$(MODES),$(eval $(call MODE_V3_RULE,$(m)))))
$(BUILD)/obj/src/render/render.o: MODULE_CFLAGS += $(if $(ISA_V3),-DRENDER_ISA_V3)

$(LIB): $(COMMON_OBJ) $(MODAL_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BIN): $(BUILD)/obj/src/cli/main.o $(LIB)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $^ $(LIBS)

# --- tests -----------------------------------------------------------------
$(BUILD)/tests/%: tests/unit/%.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Itests $(ALL_CFLAGS) $(LDFLAGS) -o $@ $< tests/support.c $(LIB) $(LIBS) -lcmocka

unit-tests: $(if $(HAVE_CMOCKA),$(TEST_BIN)) $(BIN)

# The include graph follows the rooms of docs/architecture.md.
check-deps:
	@sh tools/check_deps.sh

test: deps-test check-deps
	@$(MAKE) --no-print-directory unit-tests $(TEST_EXTRA)
	@sh tests/run.sh $(BUILD)

# Sanitizer build: the whole suite again under ASan+UBSan in its own tree.
asan-test: deps-test
	@$(MAKE) --no-print-directory BUILD=build-asan \
	  CFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	  LDFLAGS="-fsanitize=address,undefined" test

# Fuzzing: fuzz-smoke (CI) runs each target briefly; fuzz runs each for
# FUZZ_SECONDS and keeps the minimised corpus in tests/fuzz/corpus/.
FUZZ_SECONDS ?= 60
fuzz-smoke: deps-fuzz
	@sh tests/fuzz/run.sh $(FUZZ_SECONDS)

fuzz: deps-fuzz
	@sh tests/fuzz/run.sh $(FUZZ_SECONDS) keep

# --- demo and bench --------------------------------------------------------
demo: deps-demo
	@$(MAKE) --no-print-directory all
	@mkdir -p out
	$(BIN) render scenes/fig1.scene -o out/fig1.png --dl out/fig1.dl5080 --size 1024x1024 --aa 4
	@if [ -s out/fig1.dl5080 ]; then $(BIN) dl2png out/fig1.dl5080 out/fig1-5081.png; fi
	@ls -l out

bench: deps-demo all
	@sh bench/run.sh $(BIN)

# --- install ---------------------------------------------------------------
# The binary, the man page, and under PREFIX/share/maprt the scenes (with
# the images they name; `maprt render fig1` finds them there), the docs and
# the README.
SHARE_SCENES := $(wildcard scenes/*.scene scenes/*.png scenes/*.sh)
install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 \
	  $(DESTDIR)$(DATADIR)/scenes $(DESTDIR)$(DATADIR)/docs
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/maprt
	$(if $(MPI_BIN),install -m 755 $(MPI_BIN) $(DESTDIR)$(PREFIX)/bin/maprt-mpi)
	install -m 644 docs/maprt.1 $(DESTDIR)$(PREFIX)/share/man/man1/maprt.1
	install -m 644 $(SHARE_SCENES) $(DESTDIR)$(DATADIR)/scenes
	install -m 644 docs/*.md README.md $(DESTDIR)$(DATADIR)/docs

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/maprt $(DESTDIR)$(PREFIX)/bin/maprt-mpi \
	  $(DESTDIR)$(PREFIX)/share/man/man1/maprt.1
	rm -rf $(DESTDIR)$(DATADIR)

clean:
	rm -rf build build-asan build-fuzz out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

print-libs:
	@echo $(LIBS)

# --- race against peers (POV-Ray 3.7 and a minimal hand-written tracer) ---
# The minimal tracer is compiled with maprt's own CFLAGS, and as maprt's
# tracer once more for x86-64-v3 (bench/peers/run.sh runs the one of the
# same code as maprt's): a ratio between them then measures the programs,
# not the optimisation levels.
$(BUILD)/bench/minimal: bench/peers/minimal.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -o $@ $< -lm
$(BUILD)/bench/minimal-v3: bench/peers/minimal.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(V3_CFLAGS) -o $@ $< -lm

# The timer of every run of the two races (microseconds of CPU).
$(BUILD)/bench/cputime: bench/peers/cputime.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -o $@ $<

# Every input of the fixed-point reciprocal square root against long
# double (the bound fx.h states; docs/numerics.md).
$(BUILD)/tools/rsqrt_bound: tools/rsqrt_bound.c src/num/fx.c src/num/fx.h
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -fopenmp -Isrc -o $@ tools/rsqrt_bound.c src/num/fx.c $(LDFLAGS) -lm

.PHONY: check-rsqrt
check-rsqrt: $(BUILD)/tools/rsqrt_bound
	$(BUILD)/tools/rsqrt_bound

.PHONY: bench-peers
bench-peers: deps all $(BUILD)/bench/minimal $(if $(ISA_V3),$(BUILD)/bench/minimal-v3) $(BUILD)/bench/cputime
	@sh bench/peers/run.sh $(BIN) $(BUILD)/bench/minimal $(BUILD)/bench/cputime

.PHONY: bench-grow bench-phases
# $(call grow_decks,SCRIPT): SCRIPT (bench/peers) on the three decks of
# grow.sh, each table under its name
define grow_decks
	@echo "grid of parts alike:"
	@sh bench/peers/$(1) $(BIN) $(BUILD)/bench/cputime
	@echo "parts turned each its own way (GROW_TURN=1):"
	@GROW_TURN=1 sh bench/peers/$(1) $(BIN) $(BUILD)/bench/cputime
	@echo "parts turned and each of a size of its own, none a copy (GROW_TURN=1 GROW_VARY=1):"
	@GROW_TURN=1 GROW_VARY=1 sh bench/peers/$(1) $(BIN) $(BUILD)/bench/cputime
endef

bench-grow: deps-bench all $(BUILD)/bench/cputime
	$(call grow_decks,grow.sh)

bench-phases: deps-bench all $(BUILD)/bench/cputime
	$(call grow_decks,phases.sh)
