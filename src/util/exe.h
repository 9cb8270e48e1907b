/* exe — finding helper programs (gnuplot, hercules) on PATH. */
#ifndef EXE_H
#define EXE_H

/* 1 when an executable file named name (no slash) is in a PATH directory. */
int exe_on_path(const char *name);
#endif
