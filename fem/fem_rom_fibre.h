/* fem_rom_fibre.h: the mixed fibre field of the reduced model (internal to fem_rom*.c).
 *
 * Owns: the factor of G = sum_f W_f Q_f Q_f^T over the kept fibres (fem_rom.h csfRom.mf), the
 * mixed fibres' share of the reduced residual and tangent, and their stress state's update in
 * the reduced Newton. The public entry is csf_romSetFibreBasis (fem_rom.h).
 *
 * The weighted (hyper-reduced) model. ECSW keeps a subset K of the fibres with weights
 * w_f >= 0 (fem_rom.h csfRom.w[CSF_ROM_SET_FIBRE]); the weight enters every sum over fibres,
 * through W_f = w_f EA_f L0_f (N), and nothing else:
 *   G_w = sum_{f in K} W_f Q_f Q_f^T,   E^_w(q) = G_w^-1 sum_{f in K} W_f Q_f E_f(q),
 *   Pi_w(q) = sum_{f in K} W_f psi(Q_f . E^_w(q)).
 * Pi_w is an energy of q alone for any w >= 0 with G_w positive definite, so its gradient
 * r_w = sum_K W_f S*_f dE_f/dq (S* = Q G_w^-1 sum_K W Q S(Ebar)) is conservative and its
 * Hessian sum_K W_f S*_f d2E_f/dq2 + Z_w^T C_w Z_w (Z_w = G_w^-1 B_w, B_w = sum_K W Q dE/dq,
 * C_w = sum_K W S'(Ebar) Q Q^T) is symmetric: the derivation of fem_rom_fibre.c with every sum
 * restricted to K and weighted. With K every fibre and w = 1 it is the unreduced model.
 * What the weights must reproduce, so that Pi_w's gradient at a training state is the unreduced
 * one: (i) G (constant in q: its mf (mf + 1) / 2 entries, weighted sums of W_f Q_fi Q_fj);
 * (ii) sum W Q E (then E^_w = E^ and every Ebar_f is the unreduced one); (iii) sum W Q S(Ebar)
 * (then S*_w = S*); (iv) the force sum sum W S*_f dE_f/dq at that S*. The ECSW rows
 * (csf_romFibreElementForces, and the G rows of `crawlsim rom ecsw-matrix`) are these sums'
 * terms, fibre by fibre; weights that reproduce all four reproduce r exactly (tested with
 * weights in the rows' null space, tests/fem/test_fem_rom_fibre.c). The tangent's B and C are
 * not fitted: they follow from the same weights. */
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

/* The ECSW rows of the mixed fibres (fem_rom.h csf_romElementForces; r->mf > 0) at q: for every
 * fibre f of the FE model, whatever r's weights, row f of G (nfib x (n + 2 mf)) holds its reduced
 * force at the unreduced S*_f (N; E^, S* over every fibre at weight 1), then W_f Q_f E_f and
 * W_f Q_f S(Ebar_f) (N, W_f = EA_f L0_f): summed over the fibres, the unreduced model's fibre
 * residual, G E^ and G s^. Returns 0, -1 out of memory or when G is singular. */
int csf_romFibreElementForces(const csfRom* r, const double* q, double* G);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_FIBRE_H */
