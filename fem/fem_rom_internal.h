/* fem_rom_internal.h: what fem_rom.c (the model, its tensors, its data), fem_rom_eval.c (the
 * reduced forces) and fem_rom_newton.c (the reduced Newton) share (internal to fem_rom*.c;
 * fem_rom.h is the public header). */
#ifndef CS_FEM_ROM_INTERNAL_H
#define CS_FEM_ROM_INTERNAL_H

#include "fem_rom.h"

#ifdef __cplusplus
extern "C" {
#endif

/* H(q) = H0 + sum_k q_k H_k of chamber c into Hq (n x n), from the chamber tensors of
 * csf_romChamberTensors (fem_rom.c) */
void csf_romChamberHessian(const csfRom* r, int c, const double* q, double* Hq);

/* element displacement ue (3 nn) = V_e q over the element's nodes (fem_rom_eval.c) */
void csf_romGather(const csfRom* r, const double* q, int nn, const int* nodes, double* ue);

#ifdef __cplusplus
}
#endif

#endif /* CS_FEM_ROM_INTERNAL_H */
