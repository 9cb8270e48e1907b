# Optional MPI build (docs/cluster.md): MPI=auto (default) builds
# $(BUILD)/maprt-mpi beside $(BUILD)/maprt when pkg-config finds Open MPI,
# MPI=1 requires it, MPI=0 builds no maprt-mpi. Only src/cli/cli_mpi.c sees
# mpi.h, compiled a second time with MAPRT_MPI for maprt-mpi; maprt itself
# links no MPI: libmpi and the six libraries it brings cost every process
# 2.2 M instructions of relocation at start-up (1.2 ms), and a maprt that
# does not need them runs where Open MPI is not installed.
MPI ?= auto
MPI_FOUND := $(shell pkg-config --exists ompi-c 2>/dev/null && echo 1)
ifeq ($(MPI),auto)
MPI := $(if $(MPI_FOUND),1,0)
endif
ifeq ($(MPI),1)
ifeq ($(MPI_FOUND),)
$(error MPI=1 but pkg-config finds no ompi-c: apt-get install libopenmpi-dev openmpi-bin)
endif
MPI_BIN := $(BUILD)/maprt-mpi
all: $(MPI_BIN)
TEST_EXTRA += $(MPI_BIN)
$(BUILD)/obj-mpi/src/cli/cli_mpi.o: src/cli/cli_mpi.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -DMAPRT_MPI $(shell pkg-config --cflags ompi-c) -c $< -o $@
# the MPI cli_mpi.o comes before the library, so the archive's own is not used
$(MPI_BIN): $(BUILD)/obj/src/cli/main.o $(BUILD)/obj-mpi/src/cli/cli_mpi.o $(LIB)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $^ $(LIBS) $(shell pkg-config --libs ompi-c)
endif
