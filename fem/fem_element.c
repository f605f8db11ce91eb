/* fem_element.c: element kernels (fem_element.h).
 *
 * Rationale.
 * Element: quadratic tetrahedra (Tet10, as ABAQUS C3D10H in the paper), 4-point rule.
 * Incompressibility: mean dilatation (three-field Hu-Washizu with element-constant dilatation
 * theta = v_e / V_e and pressure p = U'(theta)), i.e. the P2/P0 pair, which is inf-sup stable on
 * tetrahedra. Because theta and p are element-local they are condensed exactly, so the global
 * unknowns are the displacements only and the discrete problem is the minimum of
 *   Pi(u) = sum_e [ int_e W_dev(C_bar) dV + V_e U(theta_e) ] - W_ext(u),
 *   W_dev = C10 (I1b - 3) + C20 (I1b - 3)^2, I1b = J^(-2/3) tr C, U = kappa/2 (theta - 1)^2,
 * whose Hessian is the (symmetric) consistent tangent:
 *   K_e = int G^T (A_dev + p d2J/dFdF) G dV + (kappa / V_e) g g^T,  g = int cof(F) : G dV.
 * Rejected: plain P2 with pointwise U(J) (locks for kappa >> mu: measured in test_fem_locking),
 * Taylor-Hood P2/P1 (continuous pressure unknowns make the global system a saddle point; more
 * unknowns and an indefinite factorisation for the same accuracy here).
 * Pressure: follower load on the deformed faces, f_a = -p int N_a (x_,s x x_,t) ds dt with the
 * outward (body) normal; its load stiffness is assembled exactly (non-symmetric per face,
 * symmetric in sum over a closed chamber). 6-point degree-4 rule on Tri6.
 * Fibres: 2-node trusses with Green strain, E_f S = E_f E, energy EA L0 E^2 / 2, whose end points
 * are interpolated from the host tetrahedra (embedded, tied). */
#include "fem_element.h"

#include <math.h>
#include <string.h>

#include "fem_mesh.h"

/* 4-point degree-2 rule on the reference tetrahedron (volume 1/6): abscissae and weight */
#define QA 0.5854101966249685
#define QB 0.1381966011250105
static const double kTetQ[4][3] = {{QB, QB, QB}, {QA, QB, QB}, {QB, QA, QB}, {QB, QB, QA}};
static const double kTetW = 1.0 / 24.0;

/* 6-point degree-4 rule on the reference triangle (area 1/2), Dunavant */
static const double kTriQ[6][3] = {
    {0.445948490915965, 0.445948490915965, 0.223381589678011 / 2},
    {0.108103018168070, 0.445948490915965, 0.223381589678011 / 2},
    {0.445948490915965, 0.108103018168070, 0.223381589678011 / 2},
    {0.091576213509771, 0.091576213509771, 0.109951743655322 / 2},
    {0.816847572980459, 0.091576213509771, 0.109951743655322 / 2},
    {0.091576213509771, 0.816847572980459, 0.109951743655322 / 2}};


int csf_tetReference(const double X[30], double dNdX[120], double wq[4], double* vol) {
  *vol = 0;
  /* dN/dX = dN/dxi J0^-1, J0 = dX/dxi */
  for (int g = 0; g < CSF_TET_NQ; g++) {
    double dN[30], J0[9] = {0}, Ji[9];
    csf_tet10Shape(kTetQ[g], NULL, dN);
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        for (int d = 0; d < 3; d++) {
          J0[3 * i + d] += X[3 * a + i] * dN[3 * a + d];
        }
      }
    }
    const double det = csf_inv3(J0, Ji);
    if (!(det > 0)) {
      return -1;
    }
    double* out = dNdX + 30 * g;
    for (int a = 0; a < 10; a++) {
      for (int J2 = 0; J2 < 3; J2++) {
        out[3 * a + J2] =
            dN[3 * a] * Ji[J2] + dN[3 * a + 1] * Ji[3 + J2] + dN[3 * a + 2] * Ji[6 + J2];
      }
    }
    wq[g] = kTetW * det;
    *vol += kTetW * det;
  }
  return 0;
}


void csf_tetQuadratureShape(double Nq[4][10]) {
  for (int g = 0; g < CSF_TET_NQ; g++) {
    csf_tet10Shape(kTetQ[g], Nq[g], NULL);
  }
}



/* add s * d2J/dFdF (J = det F) to A; Fi = F^-1 */
static void addD2J(double A[81], const double Fi[9], double J, double s) {
  for (int i = 0; i < 3; i++) {
    for (int J2 = 0; J2 < 3; J2++) {
      for (int k = 0; k < 3; k++) {
        for (int L = 0; L < 3; L++) {
          A[9 * (3 * i + J2) + 3 * k + L] +=
              s * J * (Fi[3 * J2 + i] * Fi[3 * L + k] - Fi[3 * J2 + k] * Fi[3 * L + i]);
        }
      }
    }
  }
}



/* F = I + grad u at quadrature point g of element e; u gathered in ue (30) */
static void defGrad(const double* dNdX, const double ue[30], double F[9]) {
  for (int i = 0; i < 9; i++) {
    F[i] = (i % 4 == 0) ? 1.0 : 0.0;
  }
  for (int a = 0; a < 10; a++) {
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        F[3 * i + J2] += ue[3 * a + i] * dNdX[3 * a + J2];
      }
    }
  }
}


int csf_tetKernel(const csfMaterial* mat, const double dNdX[120], const double wq[4], double vol,
                  const double ue[30], double theta_e, double re[30], double* ke,
                  double* vratio_out, double gvec[30], double* jmin_out) {
  memset(re, 0, 30 * sizeof(double));
  if (ke) {
    memset(ke, 0, 900 * sizeof(double));
  }
  const double* dNe = dNdX;
  const double* we = wq;
  double F[4][9], Fi[4][9], J[4];
  double jmin = INFINITY;
  /* pass 1: deformation and element dilatation theta = v / V */
  double vcur = 0;
  for (int g = 0; g < 4; g++) {
    defGrad(dNe + 30 * g, ue, F[g]);
    J[g] = csf_inv3(F[g], Fi[g]);
    if (!(J[g] > 0)) {
      return 1;
    }
    jmin = fmin(jmin, J[g]);
    vcur += we[g] * J[g];
  }
  const double vratio = vcur / vol;
  const int mixed = mat->form == CSF_FORM_MIXED_P0;
  /* three-field u-theta-p with theta, p condensed: the residual carries the condensed pressure
   * p_state + kappa (v/V - theta_e) = kappa (v/V - 1); the geometric stiffness uses the state
   * pressure p_state = kappa (theta_e - 1), which Newton updates by the linearised constraint
   * (fem_newton.c). At convergence theta_e = v/V and both agree. */
  const double p_res = mixed ? mat->kappa * (vratio - 1.0) : 0.0;
  const double p_tan = mixed ? mat->kappa * (theta_e - 1.0) : 0.0;
  memset(gvec, 0, 30 * sizeof(double));
  for (int g = 0; g < 4; g++) {
    const double* dN = dNe + 30 * g;
    double P[9], A[81];
    csf_yeohDev(mat->C10, mat->C20, F[g], NULL, P, ke ? A : NULL);
    /* volumetric part: mixed p (element constant) or pointwise U'(J), U''(J) */
    const double ppt = mixed ? mat->kappa_pt * (J[g] - 1.0) : mat->kappa * (J[g] - 1.0);
    const double pv = p_res + ppt;
    const double kcc = mixed ? mat->kappa_pt : mat->kappa; /* pointwise bulk stiffness */
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        P[3 * i + J2] += pv * J[g] * Fi[g][3 * J2 + i];
      }
    }
    if (ke) {
      addD2J(A, Fi[g], J[g], p_tan + ppt);
      if (kcc != 0.0) {
        /* pointwise bulk term kcc cof x cof */
        for (int iJ = 0; iJ < 9; iJ++) {
          double ci = J[g] * Fi[g][3 * (iJ % 3) + iJ / 3];
          for (int kL = 0; kL < 9; kL++) {
            double ck = J[g] * Fi[g][3 * (kL % 3) + kL / 3];
            A[9 * iJ + kL] += kcc * ci * ck;
          }
        }
      }
    }
    const double w = we[g];
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        double s = 0;
        for (int J2 = 0; J2 < 3; J2++) {
          s += P[3 * i + J2] * dN[3 * a + J2];
        }
        re[3 * a + i] += w * s;
        if (mixed) {
          double c = 0;
          for (int J2 = 0; J2 < 3; J2++) {
            c += J[g] * Fi[g][3 * J2 + i] * dN[3 * a + J2];
          }
          gvec[3 * a + i] += w * c;
        }
      }
    }
    if (ke) {
      /* M_a[i][kL] = sum_J dN_aJ A[iJ][kL]; K_ab,ik += w sum_L M_a[i][kL] dN_bL */
      for (int a = 0; a < 10; a++) {
        double M[3][9];
        for (int i = 0; i < 3; i++) {
          for (int kL = 0; kL < 9; kL++) {
            M[i][kL] = dN[3 * a] * A[9 * (3 * i) + kL] + dN[3 * a + 1] * A[9 * (3 * i + 1) + kL] +
                       dN[3 * a + 2] * A[9 * (3 * i + 2) + kL];
          }
        }
        for (int b = 0; b < 10; b++) {
          const double* db = dN + 3 * b;
          for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
              ke[30 * (3 * a + i) + 3 * b + k] +=
                  w * (M[i][3 * k] * db[0] + M[i][3 * k + 1] * db[1] + M[i][3 * k + 2] * db[2]);
            }
          }
        }
      }
    }
  }
  if (mixed && ke) {
    const double s = mat->kappa / vol;
    for (int q = 0; q < 30; q++) {
      for (int r = 0; r < 30; r++) {
        ke[30 * q + r] += s * gvec[q] * gvec[r];
      }
    }
  }
  *vratio_out = vratio;
  *jmin_out = jmin;
  return 0;
}


void csf_tetCauchy(const csfMaterial* mat, const double dNdX[120], const double ue[30],
                   double vratio, double sigma[6]) {
  memset(sigma, 0, 6 * sizeof(double));
  for (int g = 0; g < CSF_TET_NQ; g++) {
    double F[9], Fi[9], P[9];
    defGrad(dNdX + 30 * g, ue, F);
    double J = csf_inv3(F, Fi);
    if (!(J > 0)) {
      continue;
    }
    csf_yeohDev(mat->C10, mat->C20, F, NULL, P, NULL);
    const double pv = mat->form == CSF_FORM_MIXED_P0
                          ? mat->kappa * (vratio - 1.0) + mat->kappa_pt * (J - 1.0)
                          : mat->kappa * (J - 1.0);
    /* sigma = P F^T / J + pv I */
    double s[9];
    for (int i = 0; i < 3; i++) {
      for (int k = 0; k < 3; k++) {
        s[3 * i + k] = (P[3 * i] * F[3 * k] + P[3 * i + 1] * F[3 * k + 1] +
                        P[3 * i + 2] * F[3 * k + 2]) /
                           J +
                       (i == k ? pv : 0.0);
      }
    }
    sigma[0] += 0.25 * s[0], sigma[1] += 0.25 * s[4], sigma[2] += 0.25 * s[8];
    sigma[3] += 0.25 * s[1], sigma[4] += 0.25 * s[5], sigma[5] += 0.25 * s[2];
  }
}



static void cross(const double a[3], const double b[3], double r[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}


void csf_faceKernel(const double xf_flat[18], double p, double fe[18], double* kfe, double* vol) {
  const double(*xf)[3] = (const double(*)[3])xf_flat;
  memset(fe, 0, 18 * sizeof(double));
  if (kfe) {
    memset(kfe, 0, 18 * 18 * sizeof(double));
  }
  double v = 0;
  for (int q = 0; q < CSF_TRI_NQ; q++) {
    double N[6], dN[12], xs[3] = {0, 0, 0}, xt[3] = {0, 0, 0}, nrm[3];
    csf_tri6Shape(kTriQ[q][0], kTriQ[q][1], N, dN);
    const double w = kTriQ[q][2];
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        xs[i] += dN[2 * a] * xf[a][i];
        xt[i] += dN[2 * a + 1] * xf[a][i];
      }
    }
    cross(xs, xt, nrm);
    double xq[3] = {0, 0, 0};
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        fe[3 * a + i] -= p * w * N[a] * nrm[i];
        xq[i] += N[a] * xf[a][i];
      }
    }
    v -= w * (xq[0] * nrm[0] + xq[1] * nrm[1] + xq[2] * nrm[2]) / 3.0;
    if (kfe) {
      /* d(f_a)/d(x_bk) = -p w N_a (dN_b,s e_k x x_t + dN_b,t x_s x e_k); K = -df/dx */
      for (int b = 0; b < 6; b++) {
        for (int k = 0; k < 3; k++) {
          double ek[3] = {0, 0, 0}, c1[3], c2[3];
          ek[k] = 1.0;
          cross(ek, xt, c1);
          cross(xs, ek, c2);
          for (int a = 0; a < 6; a++) {
            for (int i = 0; i < 3; i++) {
              kfe[18 * (3 * a + i) + 3 * b + k] +=
                  p * w * N[a] * (dN[2 * b] * c1[i] + dN[2 * b + 1] * c2[i]);
            }
          }
        }
      }
    }
  }
  *vol = v;
}


int csf_fibreKernel(int nn, const double* c, const double* x, double L0, double EA,
                    double S_state, int tension_only, int geo_tension, double* rf, double* kf,
                    double* E_out, double d_out[3]) {
  double dvec[3] = {0, 0, 0};
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      dvec[i] += c[a] * x[3 * a + i];
    }
  }
  const double E = 0.5 * ((dvec[0] * dvec[0] + dvec[1] * dvec[1] + dvec[2] * dvec[2]) /
                              (L0 * L0) -
                          1.0);
  /* tension only, smoothed: stress measure S(E) = E above +delta, (E + delta)^2 / (4 delta) in
   * |E| < delta, 0 below -delta (C1: no on/off chatter). The geometric term uses the state
   * stress S_state updated by the linearised strain (fem_newton.c): with the actual S the
   * first Newton step of a bending increment stretches every rotated fibre at second order
   * (E ~ phi^2 / 2, force EA E ~ N), the residual explodes and Newton cycles (measured on the
   * baseline actuator); a compression-carrying truss adds a negative geometric stiffness that
   * lets the thin embedded fibre buckle element by element. */
  double S, dS;
  csf_fibreLaw(tension_only, E, &S, &dS);
  *E_out = E;
  d_out[0] = dvec[0], d_out[1] = dvec[1], d_out[2] = dvec[2];
  if (!(S != 0.0 || dS != 0.0 || S_state != 0.0)) {
    return 0;
  }
  /* dW/dd = EA S d / L0; tangent EA / L0 (S_state I + S'(E) d d^T / L0^2) */
  double fd[3], H[9];
  /* optional: the compressive part of the geometric stiffness is left out of the tangent (the
   * residual keeps it): an embedded truss in compression is held laterally by the matrix, which
   * the truss element does not know of, so its -EA|S|/L0 lateral stiffness would only make K
   * indefinite (modified Newton, same solution) */
  const double Sg = geo_tension ? fmax(S_state, 0.0) : S_state;
  for (int i = 0; i < 3; i++) {
    fd[i] = EA * S * dvec[i] / L0;
    for (int k = 0; k < 3; k++) {
      H[3 * i + k] = EA / L0 * ((i == k ? Sg : 0.0) + dS * dvec[i] * dvec[k] / (L0 * L0));
    }
  }
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      rf[3 * a + i] = c[a] * fd[i];
    }
  }
  if (kf) {
    const int ld = 3 * nn;
    for (int a = 0; a < nn; a++) {
      for (int b = 0; b < nn; b++) {
        for (int i = 0; i < 3; i++) {
          for (int k = 0; k < 3; k++) {
            kf[ld * (3 * a + i) + 3 * b + k] = c[a] * c[b] * H[3 * i + k];
          }
        }
      }
    }
  }
  return 1;
}
