/* fem_bend_branch.h: the sweep's view of a bifurcation (internal to fem/, used by fem_bend.c).
 *
 * Owns: the chamber volumes of a state by face tag, the asymmetry of twin chambers (two
 * pressurised chambers of one segment at the same ratio: a mirror pair, Omega1 / Omega2 at
 * (+b, +b) / (+b, -b)), and the one-line description of a bifurcation and its critical mode
 * that csf_bend reports (csfBendInfo.bifurcation_note).
 * Units: mm, mm^3, MPa, degrees. */
#ifndef CS_FEM_BEND_BRANCH_H
#define CS_FEM_BEND_BRANCH_H

#include <stddef.h>

#include "fem_actuator.h"
#include "fem_path.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Volume enclosed by the faces with tag `tag` in the current configuration (d->u), mm^3: the
 * divergence theorem over each Tri6 face split into its four flat sub-triangles (the faces'
 * normals point into the chamber, fem_mesh.h). Exact for the faceted surface of a closed
 * chamber, second order in the element size for the curved one. */
double csf_chamberVolume(const csfModel* m, const csfData* d, int tag);

/* Per segment s, (V_j - V_k) / (V_j + V_k) of its two pressurised chambers j < k when exactly
 * two have the same non-zero ratio (NAN otherwise) in asym[s]; returns the largest modulus
 * (NAN when no segment has such a pair). A path that keeps the actuator's mirror symmetry has
 * it near 0 (the mesh's own asymmetry: ~1e-3); a branch that breaks it does not. */
double csf_bendChamberAsymmetry(const csfModel* m, const csfData* d,
                                const double ratio[CSR_NSEG][CSR_NCHAMBER],
                                double asym[CSR_NSEG]);

/* Where a reference point lies in the actuator's section and length (segment or joint; the
 * web between two chambers, a chamber's outer wall, or near a chamber), as text. */
void csf_bendDescribePoint(const csrActuator* act, const double X[3], char* out, size_t sz);

/* The report line of a bifurcation: pressure and angle of the first state past it, the critical
 * mode (eigenvalue, convergence, volume component, where it is largest), the switched branch
 * (perturbation sign and size, its component along the mode, negative pivots, chamber
 * asymmetry) or why none was accepted. */
void csf_bendBifurcationNote(const csrActuator* act, const csfLimitResult* res, double a_bif,
                             double amp, double asym_branch, char* out, size_t sz);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_BEND_BRANCH_H */
