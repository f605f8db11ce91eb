/* fem_rom_mixed.h: the mixed reduced model's pressure-space algebra (internal to fem_rom*.c).
 *
 * Owns: the factor of A = sum_e w_e (V_e / kappa) P_e P_e^T over the kept Tet10s (fem_rom.h,
 * csfRom.m) and the solve A x = b. The evaluation that uses them is csf_romEvaluate. */
#ifndef CS_FEM_ROM_MIXED_H
#define CS_FEM_ROM_MIXED_H

#include "core_status.h"
#include "fem_rom.h"

#ifdef __cplusplus
extern "C" {
#endif

/* (Re)factor A over r's kept Tet10s and weights into r->A_chol (m > 0). CS_ERR_ARG when A is
 * not positive definite. */
csStatus csf_romMixedFactor(csfRom* r, csError* err);

/* Factor A into L (m x m, lower Cholesky factor) over the kept Tet10s and their weights
 * (all = 0) or over every Tet10 at weight 1 (all = 1: the unreduced model's A, which the ECSW
 * fit's element rows need whatever the rom's weights). CS_ERR_ARG when not positive definite. */
csStatus csf_romMixedFactorInto(const csfRom* r, int all, double* L, csError* err);

/* The part of csf_romSetPressureBasis and csf_romSetFibreBasis that does not depend on the
 * basis: checks B (rows x m, m >= 0, finite; `what` and `row` name the basis and its rows in the
 * error), then replaces *basis by a copy of B and *chol by an m x m buffer for its factor (both
 * NULL for m = 0), freeing the old ones. On an error nothing changes. */
csStatus csf_romBasisReplace(int rows, int m, const double* B, const char* what,
                             const char* row, double** basis, double** chol, csError* err);

/* In-place Cholesky factor of the symmetric matrix whose lower triangle L (m x m) holds:
 * -1, or the first column whose pivot is not above 1e-12 of the largest diagonal entry. */
int csf_romCholesky(int m, double* L);

/* x = A^-1 x (m), in place, from r->A_chol. */
void csf_romMixedSolve(const csfRom* r, double* x);

/* x = A^-1 x (m), in place, from the factor L of csf_romMixedFactorInto. */
void csf_romMixedSolveWith(int m, const double* L, double* x);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_MIXED_H */
