/* core_nvector.h: SUNDIALS' serial vector kernels compiled with the project (core_nvector.c
 * says why: Debian's library is built without optimisation), the same arithmetic in the same
 * order, so a run gives the same bits (tests/robot/test_rod_nvector.c compares every operation).
 * Owns nothing: it rewrites the operation table of the caller's vector. */
#ifndef CORE_NVECTOR_H
#define CORE_NVECTOR_H

#include <nvector/nvector_serial.h>

/* Replace the serial vector v's kernels by the project-compiled ones (same arithmetic); the
 * vectors CVODE clones from it (its work vectors) inherit them. */
void cs_nvectorFastOps(N_Vector v);

#endif
