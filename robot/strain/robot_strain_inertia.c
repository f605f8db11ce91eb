/* robot_strain_inertia.c: the strain leg's inertia (robot_strain.h, robot_strain_internal.h): the
 * points' body twists V_p = G_p u, the mass matrix Σ_p G_pᵀ M_p G_p by composite inertias and its
 * matrix-free product, and the read-outs that weigh the points by their mass (kinetic energy,
 * momentum, Σ m x). The step that uses them is robot_strain_dyn.c; the notation is its header's
 * (G_p = [Ad(g_p⁻¹), J_p], M_p the Simpson weight times the section's mass per length). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"


/* V = G_p (V_b, η) at point p of the kinematics R, x, J (as d->R, d->x, d->J) */
static void pointTwistOf(const csrStrainModel* m, const double* Rk, const double* xk,
                         const double* Jk, int p, const double Vb[6], const double* eta,
                         double V[6]) {
  const int n = m->n;
  const double* R = Rk + 9 * p;
  const double* x = xk + 3 * p;
  /* Ad(g⁻¹) V_b = (Rᵀ ω; Rᵀ (v + ω × x)) */
  double wx[3], t[3];
  csu_cross3(wx, Vb, x);
  csu_add3(t, Vb + 3, wx);
  csu_mulMatTVec3(V, R, Vb);
  csu_mulMatTVec3(V + 3, R, t);
  /* J η over the columns that move p (pcol[p] on are zero), each row summed in j's order as
   * one row at a time, the six rows side by side (the compiler keeps them in registers) */
  const double* J = Jk + (size_t)p * 6 * n;
  const int nc = m->pcol[p];
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0;
  for (int j = 0; j < nc; j++) {
    const double e = eta[j];
    s0 += J[j] * e;
    s1 += J[n + j] * e;
    s2 += J[2 * n + j] * e;
    s3 += J[3 * n + j] * e;
    s4 += J[4 * n + j] * e;
    s5 += J[5 * n + j] * e;
  }
  V[0] += s0;
  V[1] += s1;
  V[2] += s2;
  V[3] += s3;
  V[4] += s4;
  V[5] += s5;
}


/* V = G_p u at point p (current kinematics) */
void csr_strainPointTwist_(const csrStrainModel* m, const csrStrainData* d, int p, const double Vb[6],
                           const double* eta, double V[6]) {
  pointTwistOf(m, d->R, d->x, d->J, p, Vb, eta, V);
}


/* Σ_p m_p x_p of the leg, world (t mm), at the current kinematics and base */
void csr_strainMassMomentAt_(const csrStrainModel* m, const csrStrainData* d, double X[3]) {
  double t[3] = {0, 0, 0}, w[3];
  for (int p = 0; p < m->np; p++) {
    csu_addScl3(t, t, d->x + 3 * p, m->Ms[6 * p + 3]);
  }
  csu_mulMatVec3(w, d->Rb, t);
  csu_addScl3(X, w, d->xb, m->mass);
}


/* csr_strainRows6_ (add 1) over three rows */
static void rowAccum3(double* restrict y, const double* restrict B, int ld, const double g[3],
                      int len) {
  const double g0 = g[0], g1 = g[1], g2 = g[2];
  const double *b0 = B, *b1 = B + ld, *b2 = B + 2 * ld;
  for (int j = 0; j < len; j++) {
    double t = y[j];
    t += g0 * b0[j];
    t += g1 * b1[j];
    t += g2 * b2[j];
    y[j] = t;
  }
}


/* W_M's inertia, Σ_p G_pᵀ M_p G_p (G_p = [Ad(g_p⁻¹), J_p]), by composite inertias (the
 * composite-rigid-body idea on the pieces): a point p
 * of piece k moves with the unknowns before the piece as the piece's start point s does,
 * G_p[:, before] = Ad(g_sp⁻¹) G_s[:, before] (the Jacobian recursion), so the piece's points
 * add G_s[:, before]ᵀ I_k G_s[:, before] with I_k = Σ_p Ad_spᵀ M_p Ad_sp (6 x 6), the coupling
 * G_s[:, before]ᵀ F_k with F_k = Σ_p Ad_spᵀ M_p L_p, and Σ_p L_pᵀ M_p L_p on the piece's own
 * columns (L_p = J_p on them): per point O(6 nd) instead of O(6 n²). Fills d->WMll (full),
 * d->WMlb and d->WMbb. */
void csr_strainInertiaFrom_(const csrStrainModel* m, csrStrainData* d, const double* Rk,
                            const double* xk, const double* Jk) {
  const int n = m->n;
  double* W = d->WMll;
  memset(W, 0, (size_t)n * n * sizeof(double));
  memset(d->WMlb, 0, (size_t)n * 6 * sizeof(double));
  memset(d->WMbb, 0, sizeof d->WMbb);
  /* the hip point moves with the base: Ad = I */
  for (int c = 0; c < 6; c++) {
    d->WMbb[7 * c] += m->Ms[c];
  }
  double* F = d->Gs;                 /* 6 x nd of the piece (scratch) */
  double* T = d->Gs + 6 * (6 + n);   /* I_k G_s (6 x (6 + n)) and F_kᵀ rows */
  for (int k = 0; k < m->npiece; k++) {
    const int s = m->pt0[k], c0 = m->dof0[k], nd = m->ndof[k], nu = 6 + c0;
    double I[36];
    memset(I, 0, sizeof I);
    memset(F, 0, (size_t)6 * (nd + 1) * sizeof(double));
    const double* Rs = Rk + 9 * s;
    const double* xs = xk + 3 * s;
    for (int p = s + 1; p <= m->pt0[k + 1]; p++) {
      const double* Mp = m->Ms + 6 * p;
      double Rr[9], dx[3], xr[3], A[36];
      for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
          Rr[3 * i + j] = Rs[i] * Rk[9 * p + j] + Rs[3 + i] * Rk[9 * p + 3 + j] +
                          Rs[6 + i] * Rk[9 * p + 6 + j];
        }
      }
      csu_sub3(dx, xk + 3 * p, xs);
      csu_mulMatTVec3(xr, Rs, dx);
      csr_strainAdInv_(Rr, xr, A);
      /* I += Aᵀ M_p A, F += Aᵀ M_p L_p, the piece's own block += L_pᵀ M_p L_p, each entry's
       * terms (M_p[r] A[r][a]) A[r][b], ... added in r's order (A's rows r < 3 are zero in
       * the columns a >= 3, Ad(g⁻¹) = [Rᵀ 0; -Rᵀ x^ Rᵀ]). A zero coefficient adds ±0 to a sum
       * that started at +0 (memset) and so is never -0: the same bits as skipping it */
      const double* L = Jk + (size_t)p * 6 * n + c0;
      for (int a = 0; a < 6; a++) {
        double g[6];
        for (int r = 0; r < 6; r++) {
          g[r] = Mp[r] * A[6 * r + a];
        }
        if (a < 3) {
          csr_strainRows6_(I + 6 * a, A, 6, g, 6, 1);
          csr_strainRows6_(F + nd * a, L, n, g, nd, 1);
        } else {
          rowAccum3(I + 6 * a, A + 18, 6, g + 3, 6);
          rowAccum3(F + nd * a, L + 3 * n, n, g + 3, nd);
        }
      }
      for (int i = 0; i < nd; i++) {
        double g[6];
        for (int r = 0; r < 6; r++) {
          g[r] = Mp[r] * L[r * n + i];
        }
        csr_strainRows6_(W + (size_t)(c0 + i) * n + c0, L, n, g, i + 1, 1);
      }
    }
    /* G_s = [A_s, J_s[:, 0..c0)] (6 x nu) */
    double* Gsv = T + 6 * (6 + n);
    double As[36];
    csr_strainAdInv_(Rs, xs, As);
    const double* Js = Jk + (size_t)s * 6 * n;
    for (int r = 0; r < 6; r++) {
      memcpy(Gsv + r * nu, As + 6 * r, 6 * sizeof(double));
      memcpy(Gsv + r * nu + 6, Js + r * n, (size_t)c0 * sizeof(double));
    }
    /* T = I G_s; the before-block += G_sᵀ T (base rows into WMbb / WMlb) */
    for (int r = 0; r < 6; r++) {
      csr_strainRows6_(T + r * nu, Gsv, nu, I + 6 * r, nu, 0); /* Σ_e in e's order, as before */
    }
    double* acc = Gsv + 6 * nu; /* a row of G_sᵀ T or G_sᵀ F (scratch, nu) */
    for (int i = 0; i < nu; i++) {
      const double g[6] = {Gsv[i], Gsv[nu + i], Gsv[2 * nu + i], Gsv[3 * nu + i],
                           Gsv[4 * nu + i], Gsv[5 * nu + i]};
      csr_strainRows6_(acc, T, nu, g, i + 1, 0);
      /* each entry of the row added to its block once (no branch per entry) */
      if (i < 6) {
        for (int j = 0; j <= i; j++) {
          const double t = acc[j];
          d->WMbb[6 * i + j] += t;
          if (j != i) {
            d->WMbb[6 * j + i] += t;
          }
        }
      } else {
        double* restrict lb = d->WMlb + 6 * (i - 6);
        for (int j = 0; j < 6; j++) {
          lb[j] += acc[j];
        }
        double* restrict wr = W + (size_t)(i - 6) * n;
        const double* restrict ar = acc + 6;
        for (int j = 0; j <= i - 6; j++) {
          wr[j] += ar[j];
        }
      }
    }
    /* the coupling of the piece's columns with those before: G_sᵀ F (nu x nd) */
    for (int i = 0; i < nu; i++) {
      const double g[6] = {Gsv[i], Gsv[nu + i], Gsv[2 * nu + i], Gsv[3 * nu + i],
                           Gsv[4 * nu + i], Gsv[5 * nu + i]};
      csr_strainRows6_(acc, F, nd, g, nd, 0);
      if (i < 6) {
        for (int j = 0; j < nd; j++) {
          d->WMlb[6 * (c0 + j) + i] += acc[j];
        }
      } else {
        for (int j = 0; j < nd; j++) {
          W[(size_t)(c0 + j) * n + (i - 6)] += acc[j];
        }
      }
    }
  }
  /* the lower triangle into the upper */
  for (int j = 0; j < n; j++) {
    for (int k = 0; k < j; k++) {
      W[k * n + j] = W[j * n + k];
    }
  }
}


void csr_strainInertia_(const csrStrainModel* m, csrStrainData* d) {
  csr_strainInertiaFrom_(m, d, d->R, d->x, d->J);
}


/* M u = Σ_p G_pᵀ M_p (G_p u) point by point: V_p = G_p u as pointTwist, (μ; π) = M_p V_p, and
 * G_pᵀ (μ; π) = (Ad(g_p⁻¹)ᵀ (μ; π); J_pᵀ (μ; π)) with Ad(g⁻¹)ᵀ (μ; π) = (R μ + x × R π; R π).
 * The same sum as csr_strainInertia_'s matrix times u, in another order (round-off apart) */
void csr_strainInertiaApply_(const csrStrainModel* m, const double* Rk, const double* xk,
                             const double* Jk, const double* u, double* out) {
  const int n = m->n;
  memset(out, 0, (size_t)(6 + n) * sizeof(double));
  const double* eta = u + 6;
  double* restrict ol = out + 6;
  for (int p = 0; p < m->np; p++) {
    const double* R = Rk + 9 * p;
    const double* x = xk + 3 * p;
    const double* restrict J = Jk + (size_t)p * 6 * n;
    const double* Ms = m->Ms + 6 * p;
    const int nc = m->pcol[p];
    double V[6];
    pointTwistOf(m, Rk, xk, Jk, p, u, eta, V);
    for (int r = 0; r < 6; r++) {
      V[r] *= Ms[r];
    }
    double Rm[3], Rp[3], xRp[3];
    csu_mulMatVec3(Rm, R, V);
    csu_mulMatVec3(Rp, R, V + 3);
    csu_cross3(xRp, x, Rp);
    for (int c = 0; c < 3; c++) {
      out[c] += Rm[c] + xRp[c];
      out[3 + c] += Rp[c];
    }
    /* Jᵀ (μ; π), one pass over the columns (vectorised: ol and J distinct) */
    const double v0 = V[0], v1 = V[1], v2 = V[2], v3 = V[3], v4 = V[4], v5 = V[5];
    for (int j = 0; j < nc; j++) {
      ol[j] += J[j] * v0 + J[n + j] * v1 + J[2 * n + j] * v2 + J[3 * n + j] * v3 +
               J[4 * n + j] * v4 + J[5 * n + j] * v5;
    }
  }
}


void csr_strainPointTwists_(const csrStrainModel* m, csrStrainData* d) {
  /* Vp is a function of R, x, J (changed only by csr_strainKinematics_, which counts kin_gen),
   * Vb and η: with all of them as at the last call, Vp holds these very bits already. The
   * output's contact read-out after a step's commit asks again: 32 M instructions per simulated
   * second of the flat road at 5 ms (docs/notes/performance.md "Fixed costs") */
  const size_t ne = (size_t)m->n * sizeof(double);
  if (d->vp_gen == d->kin_gen && memcmp(d->vp_Vb, d->Vb, sizeof d->Vb) == 0 &&
      memcmp(d->vp_eta, d->eta, ne) == 0) {
    return;
  }
  for (int p = 0; p < m->np; p++) {
    csr_strainPointTwist_(m, d, p, d->Vb, d->eta, d->Vp + 6 * p);
  }
  d->vp_gen = d->kin_gen;
  memcpy(d->vp_Vb, d->Vb, sizeof d->vp_Vb);
  memcpy(d->vp_eta, d->eta, ne);
}


void csr_strainPointTwistsChain_(const csrStrainModel* m, csrStrainData* d) {
  d->vp_gen = -1; /* written here, not by csr_strainPointTwists_: its memo is off */
  for (int p = 0; p < m->np; p += 2) {
    csr_strainPointTwist_(m, d, p, d->Vb, d->eta, d->Vp + 6 * p);
  }
}


void csr_strainEnergy(const csrStrainModel* m, csrStrainData* d, double* kinetic,
                      double* elastic) {
  csr_strainKinematics_(m, d, 1);
  double T = 0;
  for (int p = 0; p < m->np; p++) {
    double V[6];
    csr_strainPointTwist_(m, d, p, d->Vb, d->eta, V);
    for (int r = 0; r < 6; r++) {
      T += 0.5 * m->Ms[6 * p + r] * V[r] * V[r];
    }
  }
  /* ½ (q - q0)ᵀ K (q - q0) with K q0 = b */
  double U = 0;
  for (int j = 0; j < m->n; j++) {
    double q0 = d->b[j] / d->Kd[j];
    U += 0.5 * d->Kd[j] * (d->q[j] - q0) * (d->q[j] - q0);
  }
  *kinetic = T;
  *elastic = U;
}


void csr_strainMassMoment(const csrStrainModel* m, csrStrainData* d, double mx[3]) {
  if (d->kin_valid < 1) {
    csr_strainKinematics_(m, d, 0);
  }
  memset(mx, 0, 3 * sizeof(double));
  for (int p = 0; p < m->np; p++) {
    double R[9], x[3];
    csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, R, x);
    csu_addScl3(mx, mx, x, m->Ms[6 * p + 3]);
  }
}


void csr_strainMomentum(const csrStrainModel* m, csrStrainData* d, double P[3]) {
  csr_strainKinematics_(m, d, 1);
  memset(P, 0, 3 * sizeof(double));
  for (int p = 0; p < m->np; p++) {
    double V[6], R[9], x[3], vw[3];
    csr_strainPointTwist_(m, d, p, d->Vb, d->eta, V);
    csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, R, x);
    csu_mulMatVec3(vw, R, V + 3);
    csu_addScl3(P, P, vw, m->Ms[6 * p + 3]);
  }
}
