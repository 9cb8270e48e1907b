# Optional MPI build (docs/cluster.md): MPI=auto (default) uses Open MPI when
# pkg-config finds it, MPI=1 requires it, MPI=0 builds without. Only
# src/cli/cli_mpi.c sees mpi.h; the library is linked into the binary.
MPI ?= auto
MPI_FOUND := $(shell pkg-config --exists ompi-c 2>/dev/null && echo 1)
ifeq ($(MPI),auto)
MPI := $(if $(MPI_FOUND),1,0)
endif
ifeq ($(MPI),1)
ifeq ($(MPI_FOUND),)
$(error MPI=1 but pkg-config finds no ompi-c: apt-get install libopenmpi-dev openmpi-bin)
endif
MODULE_LIBS += $(shell pkg-config --libs ompi-c)
$(BUILD)/obj/src/cli/cli_mpi.o: MODULE_CFLAGS += -DMAPRT_MPI $(shell pkg-config --cflags ompi-c)
endif
