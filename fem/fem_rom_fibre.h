/* fem_rom_fibre.h: the mixed fibre field of the reduced model (internal to fem_rom*.c).
 *
 * Owns: the factor of G = sum_f W_f Q_f Q_f^T over the kept fibres (fem_rom.h csfRom.mf), the
 * mixed fibres' share of the reduced residual and tangent, and their stress state's update in
 * the reduced Newton. The public entry is csf_romSetFibreBasis (fem_rom.h). */
#ifndef CS_FEM_ROM_FIBRE_H
#define CS_FEM_ROM_FIBRE_H

#include "core_status.h"
#include "fem_rom.h"

#ifdef __cplusplus
extern "C" {
#endif

/* (Re)factor G over r's kept fibres and weights into r->Gf_chol (mf > 0). CS_ERR_ARG when G is
 * not positive definite. */
csStatus csf_romFibreFactor(csfRom* r, csError* err);

/* The kept fibres at d->q (r->mf > 0): their forces into rint (n), and with want_k the geometric
 * term (state S*_state, or S* with d->sync) into d->Ku's upper triangle and Z^T C Z into d->K;
 * d->fib_E and d->fib_d get each kept fibre's strain and chord. Needs d->tmp of 2 n. */
void csf_romFibresMixed(const csfRom* r, csfRomData* d, int want_k, double* rint);

/* The three-field update of the kept fibres' S*_state along alpha d->dq from the iterate's
 * strains and chords (d->fib_E0, d->fib_d0): the linearised strains projected as in an
 * evaluation. */
void csf_romFibreStates(const csfRom* r, csfRomData* d, double alpha);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_FIBRE_H */
