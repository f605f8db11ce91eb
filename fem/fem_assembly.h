/* fem_assembly.h: assembly of the FE model's residual and tangent (assembly layer).
 *
 * Owns: the sparse pattern (3x3 node blocks in scalar CSR, csf_modelFinalize), the global
 * residual and consistent tangent built from the element kernels of fem_element.h (Tet10
 * bodies in parallel, fibres, follower pressure faces, gravity and dead loads, Dirichlet rows),
 * and what is computed from an assembled state (element stresses, reactions, the dilatation
 * sync used by tangent checks). No allocation: everything lives in csfModel/csfData.
 * Units: mm, MPa, N. */
#ifndef CS_FEM_ASSEMBLY_H
#define CS_FEM_ASSEMBLY_H

#include "core_status.h"
#include "fem_model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Build the sparse pattern and the element-to-pattern maps. Loads and Dirichlet values may
 * still change afterwards (but see csf_modelSymmetric: the solver's mode is chosen at
 * csf_dataCreate). */
csStatus csf_modelFinalize(csfModel* m, csError* err);

/* What the element kernels need of csf_modelFinalize (fib_single), without the sparse pattern
 * (whose sort of every node's neighbours costs 0.5 s of CPU on the short leg's 23 409 fibres):
 * a model for a reduced model (fem_rom.h), which never assembles. m->finalized becomes
 * CSF_MODEL_KERNELS, which csf_dataCreate (the FE's solvers) refuses. */
#define CSF_MODEL_KERNELS 2
csStatus csf_modelFinalizeKernels(csfModel* m, csError* err);

/* Assemble R (and K when want_k) at the current d->u and load factor. Returns 0, > 0 when the
 * state is not physical (an inverted element: recoverable, cut the step), < 0 on fatal errors. */
int csf_assemble(const csfModel* m, csfData* d, double load, int want_k);

/* Set the dilatation state to the current displacement (theta_e = v_e/V_e); after this the
 * assembled K is the exact derivative of R (used by tangent checks). */
void csf_dataSyncVolume(const csfModel* m, csfData* d);

/* y = K x with the tangent values of the last assembly (d->kval, Dirichlet rows and columns
 * identity), x and y of length ndof (not aliased). */
void csf_tangentApply(const csfModel* m, const csfData* d, const double* x, double* y);

/* Cauchy stress averaged over the quadrature points of tetrahedron e (6: xx yy zz xy yz zx, MPa)
 * at the current d->u (d->vratio must be current: call after csf_assemble). */
void csf_tetCauchyAt(const csfModel* m, const csfData* d, int e, double sigma[6]);

/* Reaction/internal force sum over dofs with fixed[] set and a given direction (0..2), N. */
double csf_reactionSum(const csfModel* m, const csfData* d, int dir);

/* The element with the smallest pointwise J (det F at its quadrature points) of the last
 * assembly: returns that J and writes the element's reference centroid (mm, the mean of its
 * four corners) to X. Element distortion shows here long before the element's mean volume
 * (theta) moves: the mixed form keeps theta near 1 while a coarse quadratic element folds. */
double csf_worstElement(const csfModel* m, const csfData* d, double X[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ASSEMBLY_H */
