/* fem_element.h: the element kernels of the full FE model (element layer).
 *
 * Owns: the quadrature rules, the reference geometry of a Tet10, and three kernels that work on
 * element-local arrays only (no mesh, no global vectors, no Newton state), so that the assembly
 * loops (fem_assembly.h), the tests and a later reduced-order leg (hyper-reduced FE) call them
 * alike:
 *   csf_tetKernel   mixed P2/P0 Yeoh Tet10 (or plain P2): residual and consistent tangent;
 *   csf_faceKernel  follower chamber pressure on a Tri6 face: load, load stiffness, volume;
 *   csf_fibreKernel embedded two-node fibre truss tied to host Tet10 nodes.
 * Node order (VTK) as fem_mesh.h. Element vectors are node-major (3a + i), element matrices
 * row-major over them. Units: mm, MPa, N. */
#ifndef CS_FEM_ELEMENT_H
#define CS_FEM_ELEMENT_H

#include "fem_material.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSF_TET_NQ 4  /* quadrature points of a Tet10 (degree 2) */
#define CSF_TRI_NQ 6  /* quadrature points of a Tri6 pressure face (degree 4, Dunavant) */

/* Reference geometry of the Tet10 with node coordinates X (10 x 3, mm): shape gradients dN/dX
 * at the 4 quadrature points (4 x 10 x 3, 1/mm), weights times Jacobian (4, mm^3) and volume
 * (mm^3). Returns 0, or -1 if the element is inverted or degenerate at a point. */
int csf_tetReference(const double X[30], double dNdX[120], double wq[4], double* vol);

/* Shape-function values of the Tet10 at its 4 quadrature points (4 x 10), e.g. for body loads
 * f_a = rho g sum_q wq N_a(q). */
void csf_tetQuadratureShape(double Nq[4][10]);

/* Mixed (P2/P0, mean dilatation) or plain P2 Yeoh Tet10 at element displacements ue (30, mm):
 * residual re = f_int (30, N) and, if ke != NULL, the consistent tangent (30 x 30, N/mm).
 * Mixed form: the residual carries the condensed pressure kappa (v/V - 1), the geometric
 * stiffness the state pressure kappa (theta_e - 1) of the element dilatation state theta_e, and
 * the condensed bulk term (kappa / V) g g^T; at convergence theta_e = v/V and K is the Hessian
 * of the condensed energy. Outputs: v/V, g = int cof(F) : G dV (30, mm^2; zero for plain P2),
 * the smallest J at the quadrature points. Returns 1 if the element is inverted (J <= 0). */
int csf_tetKernel(const csfMaterial* mat, const double dNdX[120], const double wq[4], double vol,
                  const double ue[30], double theta_e, double re[30], double* ke,
                  double* vratio, double gvec[30], double* jmin);

/* Cauchy stress averaged over the 4 quadrature points (6: xx yy zz xy yz zx, MPa) at ue, with
 * the mixed pressure from the element volume ratio `vratio`. */
void csf_tetCauchy(const csfMaterial* mat, const double dNdX[120], const double ue[30],
                   double vratio, double sigma[6]);

/* Follower pressure p (MPa) on a Tri6 face with current node positions xf (6 x 3, mm), the
 * face oriented with (x1 - x0) x (x2 - x0) out of the body (into the chamber): nodal forces
 * fe_a = -p int N_a (x_,s x x_,t) ds dt (18, N), if kfe != NULL their load stiffness
 * kfe = -d fe / dx (18 x 18, N/mm; non-symmetric per face, symmetric in sum over a closed
 * chamber), and the face's share of the enclosed volume 1/3 int x . (-n) da (mm^3; its gradient
 * is fe / p). */
void csf_faceKernel(const double xf[18], double p, double fe[18], double* kfe, double* vol);

/* Embedded fibre truss: chord d = sum_a coef_a x_a over its nn host nodes (x: current
 * positions, nn x 3, mm): nn = 20 for a truss tied to two host tetrahedra (coef = -N_a(end 1)
 * then +N_a(end 2)), nn = 10 for one inside a single host (coef = N_a(end 2) - N_a(end 1)).
 * Green strain
 * E = (|d|^2 / L0^2 - 1) / 2, force EA S(E) (csf_fibreLaw). Residual rf (3 nn, N) with the
 * actual S(E); tangent kf (3 nn x 3 nn, N/mm) if not NULL, with the state stress S_state in the geometric
 * term (mixed treatment of the nearly inextensible fibre, as the three-field treatment of
 * incompressibility), or only its tensile part with `geo_tension`. Outputs E and d (3, mm).
 * Returns 1 if the fibre carries force or stiffness (0: slack, rf and kf not written). */
int csf_fibreKernel(int nn, const double* coef, const double* x, double L0, double EA,
                    double S_state, int tension_only, int geo_tension, double* rf, double* kf,
                    double* E_out, double d_out[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ELEMENT_H */
