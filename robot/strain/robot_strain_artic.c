/* robot_strain_artic.c: the condensation of a leg without contact onto its base by the
 * articulated recursion over its pieces (robot_strain_internal.h csr_strainCondenseArtic_).
 *
 * The step's matrix without contact (robot_strain_dyn.c, Step) is
 *   W = Σ_p G_pᵀ M_p G_p + (h τ_d + h²) [0 0; 0 K],   G_p = [Ad(g_p⁻¹), J_p],
 * and the dense path assembles its n x n leg block, factors it and solves six columns for
 * Z = W_bb - W_bl W_ll⁻¹ W_lb. The leg is a chain of pieces, and a point p of piece k (start
 * point s, end point e) moves with the unknowns before the piece as s does and with its own
 * (nd of them) through L_p = J_p[:, own]:
 *   V_p = Ad(g_sp⁻¹) V_s + L_p η_k,   and every point past e as e does.
 * So W is block-structured along the chain, and eliminating the pieces' unknowns from the tip
 * to the hip (Featherstone's articulated-body inertia, here with the strains' stiffness and
 * damping on each piece's diagonal block) needs, per piece, 6 x 6 transports and one nd x nd
 * factor. With Ẑ, ŵ the articulated impedance and wrench of everything past e (e's body frame)
 * and A = Ad(g_se⁻¹):
 *   Z_ss = I_k + Aᵀ Ẑ A,   Z_sη = F_k + Aᵀ Ẑ L_e,   Z_ηη = D_k + L_eᵀ Ẑ L_e + (h τ_d + h²) K_k,
 *   r_k = h r_l[own] - L_eᵀ ŵ,   η_k = Z_ηη⁻¹ (r_k - Z_sηᵀ V_s),
 *   Ẑ_s = Z_ss - Z_sη Z_ηη⁻¹ Z_sηᵀ,   ŵ_s = Aᵀ ŵ + Z_sη Z_ηη⁻¹ r_k,
 * with I_k = Σ_p Aᵀ_sp M_p A_sp, F_k = Σ_p Aᵀ_sp M_p L_p, D_k = Σ_p L_pᵀ M_p L_p over the
 * piece's points (the dense path's composite quantities, robot_strain_inertia.c). At the hip
 * (point 0, Ad = I): Z = diag(M_0) + Ẑ_0, ρ = h r_b - ŵ_0. The back-substitution for the
 * rates, η = y - X ΔV, runs forward: V_s = T ΔV + t (T = I, t = 0 at the hip), X_k = Y_k T,
 * y_k = Z_ηη⁻¹ r_k - Y_k t with Y_k = Z_ηη⁻¹ Z_sηᵀ, then V_e = A V_s + L_e η_k.
 * The same Z, ρ, X, y as the dense factor's to round-off (W_ll is symmetric positive definite
 * here: every Z_ηη is a principal Schur complement of it, so positive definite too), for
 * O(Σ_k (nd_k³ + 36 nd_k + nd_k² np_k)) instead of the dense assembly's O(n²) per piece and
 * the factor's n³/6. The base's blocks W_bb, W_lb (the momentum rows and the plain iterates
 * use them) come from the composite inertias Ic of the same sweep: W_lb[own] = (F_k + Aᵀ Ic_e
 * L_e)ᵀ Ad(g_s⁻¹), W_bb = diag(M_0) + Ic_0.
 *
 * With contact (artic 2) each touching shape adds -h Sᵀ A S (robot_strain_contact.c: S the
 * world rates of the shape's ends, 6 x (6 + n); A = h K_y + C_y, unsymmetric where the
 * friction's linearisation is). A shape's ends lie in one piece k (a capsule spans one of its
 * sub-intervals, the foot is the tip), so S = B [V_s; η_k] with B = [S_b Ad(g_s), S[:, own]]
 * (S's columns before the piece are B_s's transport of point s's: G_p = Ad(g_sp⁻¹) G_s there),
 * and the shape's part enters the piece's own blocks alone: I_k, F_k, D_k gain -h Bᵀ A B's
 * blocks, and F_k splits into Z_sη's F_k and Z_ηs's F'_k (transposes of each other without
 * contact). The elimination is then the same with Ẑ unsymmetric:
 *   Z_ηs = F'_k + L_eᵀ Ẑ A,   Y_k = Z_ηη⁻¹ Z_ηs (LU),   Ẑ_s = Z_ss - Z_sη Y_k,
 *   η_k = Z_ηη⁻¹ r_k - Y_k V_s,
 * the same Z, ρ, X, y as the dense LU of W_ll to round-off (block elimination in the chain's
 * order from the tip; each Z_ηη is a Schur complement of W_ll's trailing blocks). The pieces'
 * factors are kept (d->art*) for the kept iterates: their W_ll⁻¹ v is one sweep from the tip
 * (r_k, ŵ) and one from the hip (y). */
#include <math.h>
#include <string.h>

#include "robot_strain_internal.h"

#define MAXD CSR_STRAIN_MAX_PIECE_DOF


/* C = Aᵀ B A (6 x 6) for A = Ad(g⁻¹) = [Rᵀ 0; -Rᵀ x^ Rᵀ] (its block A[0..2][3..5] zero,
 * skipped); sym 1: B symmetric, the upper triangle mirrored (C symmetric), 0: B general */
static void congruence6(const double A[36], const double B[36], double C[36], int sym) {
  /* constant trip counts (the compiler unrolls them) */
  double BA[36];
  for (int r = 0; r < 6; r++) {
    const double* b = B + 6 * r;
    for (int c = 0; c < 3; c++) {
      BA[6 * r + c] = b[0] * A[c] + b[1] * A[6 + c] + b[2] * A[12 + c] + b[3] * A[18 + c] +
                      b[4] * A[24 + c] + b[5] * A[30 + c];
    }
    for (int c = 3; c < 6; c++) {
      BA[6 * r + c] = b[3] * A[18 + c] + b[4] * A[24 + c] + b[5] * A[30 + c];
    }
  }
  for (int a = 0; a < 3; a++) {
    for (int c = sym ? a : 0; c < 6; c++) {
      const double t = A[a] * BA[c] + A[6 + a] * BA[6 + c] + A[12 + a] * BA[12 + c] +
                       A[18 + a] * BA[18 + c] + A[24 + a] * BA[24 + c] + A[30 + a] * BA[30 + c];
      C[6 * a + c] = t;
      if (sym) {
        C[6 * c + a] = t;
      }
    }
  }
  for (int a = 3; a < 6; a++) {
    for (int c = sym ? a : 0; c < 6; c++) {
      const double t = A[18 + a] * BA[18 + c] + A[24 + a] * BA[24 + c] + A[30 + a] * BA[30 + c];
      C[6 * a + c] = t;
      if (sym) {
        C[6 * c + a] = t;
      }
    }
  }
}


/* Ad(g_sp⁻¹) of point p relative to point s (the poses relative to the hip) */
static void relAd(const csrStrainData* d, int s, int p, double A[36]) {
  const double* Rs = d->R + 9 * s;
  const double* xs = d->x + 3 * s;
  const double* Rp = d->R + 9 * p;
  const double* xp = d->x + 3 * p;
  double Rr[9], dx[3], xr[3];
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      Rr[3 * i + j] = Rs[i] * Rp[j] + Rs[3 + i] * Rp[3 + j] + Rs[6 + i] * Rp[6 + j];
    }
    dx[i] = xp[i] - xs[i];
  }
  for (int i = 0; i < 3; i++) {
    xr[i] = Rs[i] * dx[0] + Rs[3 + i] * dx[1] + Rs[6 + i] * dx[2];
  }
  csr_strainAdInv_(Rr, xr, A);
}


/* the piece's own sums over its points s < p <= e: I (6 x 6), F (6 x nd), D (nd x nd, upper
 * triangle and mirrored); A left as Ad(g_se⁻¹).
 * M_p = diag(J_p, m_p I3) (J_p = diag(ρI1, ρI2, ρI3) and m_p = ρA times the Simpson weight,
 * Ms; its three translational entries are the same bits by construction, robot_strain.c), and
 * with A = Ad(g_sp⁻¹) = [Rᵀ 0; -Rᵀ x^ Rᵀ] (R = R_sᵀ R_p, x = R_sᵀ (x_p - x_s)) the products
 * have the closed block forms (Featherstone's spatial inertia of a point mass and a rotor)
 *   Aᵀ M_p A = [R J_p Rᵀ + m_p (|x|² I - x xᵀ), m_p x^; -m_p x^, m_p I3],
 *   Aᵀ M_p L_p = [R J_p L_ω + x^ (m_p R L_v); m_p R L_v]   (L_p = [L_ω; L_v], 3 x nd each),
 * so each point adds to sums taken in the hip frame (dx = x_p - x_s): Σm, Σ m dx, Σ m dx dxᵀ,
 * Σ R_p J_p R_pᵀ (about 40 products instead of the Ad's 6 x 6 congruence), and to
 * G = Σ [R_p J_p L_ω + dx^ (m_p R_p L_v); m_p R_p L_v] (24 products a column instead of 36);
 * the piece then rotates them once into s's frame (R_sᵀ): I = [R_sᵀ (ΣRJRᵀ + tr(Sxx) I -
 * Sxx) R_s, c^; -c^, Σm I3] with c = R_sᵀ Σ m dx, F = diag(R_sᵀ, R_sᵀ) G. The same sums as the
 * Ad products to round-off (test_strain_model: piece_sums_are_the_ad_products). */
void csr_strainPieceSums_(const csrStrainModel* m, const csrStrainData* d, int k, double I[36],
                          double* F, double* D, double A[36]) {
  const int n = m->n, s = m->pt0[k], e = m->pt0[k + 1], c0 = m->dof0[k], nd = m->ndof[k];
  const double* Rs = d->R + 9 * s;
  const double* xs = d->x + 3 * s;
  /* hip-frame sums: Σm, Σ m dx, Σ m dx dxᵀ and Σ R J Rᵀ (upper triangles: 00 01 02 11 12 22) */
  double sm = 0, sx[3] = {0, 0, 0}, sxx[6] = {0, 0, 0, 0, 0, 0}, sj[6] = {0, 0, 0, 0, 0, 0};
  double G[6 * MAXD];
  memset(G, 0, (size_t)6 * nd * sizeof(double));
  memset(D, 0, (size_t)nd * nd * sizeof(double));
  for (int p = s + 1; p <= e; p++) {
    const double* Mp = m->Ms + 6 * p;
    const double* Rp = d->R + 9 * p;
    const double* xp = d->x + 3 * p;
    const double mp = Mp[3];
    const double dx[3] = {xp[0] - xs[0], xp[1] - xs[1], xp[2] - xs[2]};
    const double mx[3] = {mp * dx[0], mp * dx[1], mp * dx[2]};
    sm += mp;
    sx[0] += mx[0];
    sx[1] += mx[1];
    sx[2] += mx[2];
    sxx[0] += mx[0] * dx[0];
    sxx[1] += mx[0] * dx[1];
    sxx[2] += mx[0] * dx[2];
    sxx[3] += mx[1] * dx[1];
    sxx[4] += mx[1] * dx[2];
    sxx[5] += mx[2] * dx[2];
    /* R_p J_p (row i: R_p[i][c] J_c) and m_p R_p */
    double RJ[9], mR[9];
    for (int i = 0; i < 3; i++) {
      for (int c = 0; c < 3; c++) {
        RJ[3 * i + c] = Rp[3 * i + c] * Mp[c];
        mR[3 * i + c] = mp * Rp[3 * i + c];
      }
    }
    sj[0] += RJ[0] * Rp[0] + RJ[1] * Rp[1] + RJ[2] * Rp[2];
    sj[1] += RJ[0] * Rp[3] + RJ[1] * Rp[4] + RJ[2] * Rp[5];
    sj[2] += RJ[0] * Rp[6] + RJ[1] * Rp[7] + RJ[2] * Rp[8];
    sj[3] += RJ[3] * Rp[3] + RJ[4] * Rp[4] + RJ[5] * Rp[5];
    sj[4] += RJ[3] * Rp[6] + RJ[4] * Rp[7] + RJ[5] * Rp[8];
    sj[5] += RJ[6] * Rp[6] + RJ[7] * Rp[7] + RJ[8] * Rp[8];
    if (nd == 0) {
      continue;
    }
    const double* L = d->J + (size_t)p * 6 * n + c0;
    /* u = m_p R_p L_v (3 x nd), G_v += u, G_ω += R_p J_p L_ω + dx × u */
    double u[3 * MAXD];
    for (int i = 0; i < 3; i++) {
      const double* l3 = L + 3 * n;
      const double *l4 = l3 + n, *l5 = l4 + n;
      const double a0 = mR[3 * i], a1 = mR[3 * i + 1], a2 = mR[3 * i + 2];
      double* ui = u + nd * i;
      double* gi = G + nd * (3 + i);
      for (int j = 0; j < nd; j++) {
        const double t = a0 * l3[j] + a1 * l4[j] + a2 * l5[j];
        ui[j] = t;
        gi[j] += t;
      }
    }
    for (int i = 0; i < 3; i++) {
      const int i1 = i == 2 ? 0 : i + 1, i2 = i == 0 ? 2 : i - 1;
      const double a0 = RJ[3 * i], a1 = RJ[3 * i + 1], a2 = RJ[3 * i + 2];
      const double d1 = dx[i1], d2 = dx[i2];
      const double *u1 = u + nd * i2, *u2 = u + nd * i1;
      double* gi = G + nd * i;
      for (int j = 0; j < nd; j++) {
        /* (dx × u)_i = dx_{i+1} u_{i+2} - dx_{i+2} u_{i+1} */
        gi[j] += a0 * L[j] + a1 * L[n + j] + a2 * L[2 * n + j] + (d1 * u1[j] - d2 * u2[j]);
      }
    }
    for (int i = 0; i < nd; i++) {
      const double g[6] = {Mp[0] * L[i], Mp[1] * L[n + i], Mp[2] * L[2 * n + i],
                           Mp[3] * L[3 * n + i], Mp[4] * L[4 * n + i], Mp[5] * L[5 * n + i]};
      csr_strainRows6_(D + nd * i + i, L + i, n, g, nd - i, 1);
    }
  }
  for (int i = 0; i < nd; i++) {
    for (int j = 0; j < i; j++) {
      D[nd * i + j] = D[nd * j + i];
    }
  }
  /* into s's frame: c = R_sᵀ Σ m dx, I_ωω = R_sᵀ S R_s with S = ΣRJRᵀ + tr(Sxx) I - Sxx */
  const double tr = sxx[0] + sxx[3] + sxx[5];
  const double S[9] = {sj[0] + tr - sxx[0], sj[1] - sxx[1], sj[2] - sxx[2],
                       sj[1] - sxx[1], sj[3] + tr - sxx[3], sj[4] - sxx[4],
                       sj[2] - sxx[2], sj[4] - sxx[4], sj[5] + tr - sxx[5]};
  double c[3], SR[9];
  for (int i = 0; i < 3; i++) {
    c[i] = Rs[i] * sx[0] + Rs[3 + i] * sx[1] + Rs[6 + i] * sx[2];
    for (int j = 0; j < 3; j++) {
      SR[3 * i + j] = S[3 * i] * Rs[j] + S[3 * i + 1] * Rs[3 + j] + S[3 * i + 2] * Rs[6 + j];
    }
  }
  for (int a = 0; a < 3; a++) {
    for (int b = a; b < 3; b++) {
      const double t = Rs[a] * SR[b] + Rs[3 + a] * SR[3 + b] + Rs[6 + a] * SR[6 + b];
      I[6 * a + b] = t;
      I[6 * b + a] = t;
    }
  }
  /* I_ωv = c^ (rows ω, columns v), I_vω = -c^, I_vv = Σm I3 */
  const double ch[9] = {0, -c[2], c[1], c[2], 0, -c[0], -c[1], c[0], 0};
  for (int a = 0; a < 3; a++) {
    for (int b = 0; b < 3; b++) {
      I[6 * a + 3 + b] = ch[3 * a + b];
      I[6 * (3 + a) + b] = -ch[3 * a + b];
      I[6 * (3 + a) + 3 + b] = a == b ? sm : 0;
    }
  }
  /* F = diag(R_sᵀ, R_sᵀ) G */
  for (int hb = 0; hb < 2; hb++) {
    const double* g0 = G + nd * 3 * hb;
    const double *g1 = g0 + nd, *g2 = g1 + nd;
    for (int i = 0; i < 3; i++) {
      const double r0 = Rs[i], r1 = Rs[3 + i], r2 = Rs[6 + i];
      double* f = F + nd * (3 * hb + i);
      for (int j = 0; j < nd; j++) {
        f[j] = r0 * g0[j] + r1 * g1[j] + r2 * g2[j];
      }
    }
  }
  relAd(d, s, e, A);
}


/* out (6 x nd) = B (6 x 6) L (6 rows of leading dimension ld, nd columns) */
static void mul6L(const double B[36], const double* L, int ld, int nd, double* out) {
  for (int r = 0; r < 6; r++) {
    csr_strainRows6_(out + nd * r, L, ld, B + 6 * r, nd, 0);
  }
}


/* the piece that holds shape s's ends (its points in [pt0[k], pt0[k + 1]]), -1 if none */
static int shapePiece(const csrStrainModel* m, int s) {
  const int a = m->shape_a[s], b = m->shape_b[s];
  const int lo = a < b ? a : b, hi = a < b ? b : a;
  for (int k = 0; k < m->npiece; k++) {
    if (hi <= m->pt0[k + 1]) {
      return lo >= m->pt0[k] ? k : -1;
    }
  }
  return -1;
}


/* the touching shapes of piece k (d->ct[c] in piece k): -h Bᵀ A B added to the piece's blocks
 * I (6 x 6), F (6 x nd: Z_sη's), Fp (nd x 6: Z_ηs's), D (nd x nd), B = [S_b Ad(g_s), S[:, own]] */
static void pieceContact(const csrStrainModel* m, const csrStrainData* d, double h, int k,
                         double I[36], double* F, double* Fp, double* D) {
  const int n = m->n, nu = 6 + n, s = m->pt0[k], c0 = m->dof0[k], nd = m->ndof[k];
  const int w = 6 + nd;
  double Ads[36];
  int have = 0;
  for (int c = 0; c < d->nct; c++) {
    if (shapePiece(m, d->ct[c]) != k) {
      continue;
    }
    if (!have) {
      /* Ad(g_s) = Ad((g_s⁻¹)⁻¹), g_s⁻¹ = (Rᵀ, -Rᵀ x) */
      const double* R = d->R + 9 * s;
      const double* x = d->x + 3 * s;
      double Rt[9], xi[3];
      for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
          Rt[3 * i + j] = R[3 * j + i];
        }
        xi[i] = -(R[i] * x[0] + R[3 + i] * x[1] + R[6 + i] * x[2]);
      }
      csr_strainAdInv_(Rt, xi, Ads);
      have = 1;
    }
    const double* S = d->cS + (size_t)c * 6 * nu;
    const double* A = d->cA + 36 * c;
    double B[6 * (6 + MAXD)], AB[6 * (6 + MAXD)];
    for (int r = 0; r < 6; r++) {
      const double* Sr = S + (size_t)r * nu;
      csr_strainRows6_(B + w * r, Ads, 6, Sr, 6, 0);
      memcpy(B + w * r + 6, Sr + 6 + c0, (size_t)nd * sizeof(double));
    }
    for (int r = 0; r < 6; r++) {
      csr_strainRows6_(AB + w * r, B, w, A + 6 * r, w, 0);
    }
    for (int i = 0; i < w; i++) {
      const double g[6] = {B[i], B[w + i], B[2 * w + i], B[3 * w + i], B[4 * w + i],
                           B[5 * w + i]};
      double row[6 + MAXD];
      csr_strainRows6_(row, AB, w, g, w, 0);
      double* r6 = i < 6 ? I + 6 * i : Fp + 6 * (i - 6);
      double* rd = i < 6 ? F + nd * i : D + nd * (i - 6);
      for (int j = 0; j < 6; j++) {
        r6[j] += row[j] * -h;
      }
      for (int j = 0; j < nd; j++) {
        rd[j] += row[6 + j] * -h;
      }
    }
  }
}


/* y = Aᵀ x and y = A x (6 x 6, 6): each entry's six terms in order */
static void mulT6(const double A[36], const double x[6], double y[6]) {
  for (int a = 0; a < 6; a++) {
    double t = 0;
    for (int r = 0; r < 6; r++) {
      t += A[6 * r + a] * x[r];
    }
    y[a] = t;
  }
}


static void mul6(const double A[36], const double x[6], double y[6]) {
  for (int r = 0; r < 6; r++) {
    double u = 0;
    for (int c = 0; c < 6; c++) {
      u += A[6 * r + c] * x[c];
    }
    y[r] = u;
  }
}


int csr_strainCondenseArtic_(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* rl, const double rb[6], double Z[36],
                             double rho[6]) {
  const int n = m->n;
  const double cK = h * m->rpar.damping_time + h * h;
  /* with contact: every piece's blocks unsymmetric, its factor an LU, kept for the iterates */
  const int unsym = d->nct > 0;
  for (int c = 0; c < d->nct; c++) {
    if (shapePiece(m, d->ct[c]) < 0) {
      return 1;
    }
  }
  double Zh[36], wh[6], Ic[36];
  memset(Zh, 0, sizeof Zh);
  memset(wh, 0, sizeof wh);
  memset(Ic, 0, sizeof Ic);
  double F[6 * MAXD], D[MAXD * MAXD], ZL[6 * MAXD], IL[6 * MAXD], Zsn[6 * MAXD];
  double Fs[6 * MAXD], Fp[MAXD * 6]; /* with contact: Z_sη's own part, Z_ηs's */
  double Ak[CSR_ROD_MAX_PIECES][36]; /* each piece's Ad(g_se⁻¹), for the forward pass */
  for (int k = m->npiece - 1; k >= 0; k--) {
    const int s = m->pt0[k], e = m->pt0[k + 1], c0 = m->dof0[k], nd = m->ndof[k];
    double I[36], Zs[36], Ics[36];
    double* A = Ak[k];
    csr_strainPieceSums_(m, d, k, I, F, D, A);
    congruence6(A, Ic, Ics, 1);
    for (int i = 0; i < 36; i++) {
      Ics[i] += I[i];
    }
    if (unsym) {
      /* the composite (W_M's: W_bb, W_lb) keeps the inertia's F; the step's blocks gain the
       * contact's */
      memcpy(Fs, F, (size_t)6 * nd * sizeof(double));
      for (int i = 0; i < nd; i++) {
        for (int a = 0; a < 6; a++) {
          Fp[6 * i + a] = F[nd * a + i];
        }
      }
      pieceContact(m, d, h, k, I, Fs, Fp, D);
      congruence6(A, Zh, Zs, 0);
      memcpy(d->artA + 36 * k, A, 36 * sizeof(double));
    } else {
      congruence6(A, Zh, Zs, 1);
    }
    for (int i = 0; i < 36; i++) {
      Zs[i] += I[i];
    }
    double w[6];
    for (int a = 0; a < 6; a++) {
      double t = 0;
      for (int r = 0; r < 6; r++) {
        t += A[6 * r + a] * wh[r];
      }
      w[a] = t;
    }
    if (nd > 0) {
      const double* Le = d->J + (size_t)e * 6 * n + c0;
      const double* Fz = unsym ? Fs : F;
      mul6L(Zh, Le, n, nd, ZL);
      mul6L(Ic, Le, n, nd, IL);
      /* Z_sη = F + Aᵀ Ẑ L_e, and the composite's F + Aᵀ Ic L_e (into IL's place after use) */
      for (int a = 0; a < 6; a++) {
        const double g[6] = {A[a], A[6 + a], A[12 + a], A[18 + a], A[24 + a], A[30 + a]};
        csr_strainRows6_(Zsn + nd * a, ZL, nd, g, nd, 0);
        for (int j = 0; j < nd; j++) {
          Zsn[nd * a + j] += Fz[nd * a + j];
        }
      }
      double Fc[6 * MAXD];
      for (int a = 0; a < 6; a++) {
        const double g[6] = {A[a], A[6 + a], A[12 + a], A[18 + a], A[24 + a], A[30 + a]};
        csr_strainRows6_(Fc + nd * a, IL, nd, g, nd, 0);
        for (int j = 0; j < nd; j++) {
          Fc[nd * a + j] += F[nd * a + j];
        }
      }
      /* Z_ηη = D + L_eᵀ Ẑ L_e + (h τ_d + h²) K, and r_k */
      double* y = d->y + c0;
      for (int i = 0; i < nd; i++) {
        const double g[6] = {Le[i], Le[n + i], Le[2 * n + i], Le[3 * n + i], Le[4 * n + i],
                             Le[5 * n + i]};
        csr_strainRows6_(D + nd * i, ZL, nd, g, nd, 1);
        D[nd * i + i] += cK * d->Kd[c0 + i];
        double t = h * rl[c0 + i];
        for (int r = 0; r < 6; r++) {
          t -= g[r] * wh[r];
        }
        y[i] = t;
        if (unsym) {
          /* Z_ηs = F' + L_eᵀ Ẑ A: the row (L_eᵀ Ẑ)_i, then through A */
          double lz[6], za[6];
          csr_strainRows6_(lz, Zh, 6, g, 6, 0);
          csr_strainRows6_(za, A, 6, lz, 6, 0);
          for (int a = 0; a < 6; a++) {
            Fp[6 * i + a] += za[a];
          }
        }
      }
      double* Y = d->X + (size_t)6 * c0;
      if (unsym) {
        /* Y = Z_ηη⁻¹ Z_ηs and Z_ηη⁻¹ r_k by the LU; the factor, Z_sη, Y and L_e kept */
        int* piv = d->artPiv + c0;
        if (csr_strainLuFactor_(D, nd, piv)) {
          return 1;
        }
        memcpy(d->artLU + (size_t)MAXD * c0, D, (size_t)nd * nd * sizeof(double));
        memcpy(Y, Fp, (size_t)nd * 6 * sizeof(double));
        csr_strainLuSolveMulti_(D, nd, piv, Y, 6);
        csr_strainLuSolve_(D, nd, piv, y);
        memcpy(d->artY + (size_t)6 * c0, Y, (size_t)nd * 6 * sizeof(double));
        memcpy(d->artZsn + (size_t)6 * c0, Zsn, (size_t)6 * nd * sizeof(double));
        for (int r = 0; r < 6; r++) {
          memcpy(d->artL + (size_t)6 * c0 + (size_t)nd * r, Le + (size_t)r * n,
                 (size_t)nd * sizeof(double));
        }
      } else {
        if (csr_strainCholFactor_(D, nd)) {
          return 1;
        }
        /* Y = Z_ηη⁻¹ Z_sηᵀ into X's rows of the piece (nd x 6), Z_ηη⁻¹ r_k into y's */
        for (int j = 0; j < nd; j++) {
          for (int a = 0; a < 6; a++) {
            Y[6 * j + a] = Zsn[nd * a + j];
          }
        }
        csr_strainCholSolve6_(D, nd, Y);
        csr_strainCholSolve_(D, nd, y);
      }
      for (int a = 0; a < 6; a++) {
        /* row a of Z_sη Y, its six entries side by side (each one's terms in j's order) */
        double zy[6] = {0, 0, 0, 0, 0, 0};
        for (int j = 0; j < nd; j++) {
          const double z = Zsn[nd * a + j];
          const double* Yj = Y + 6 * j;
          for (int b = 0; b < 6; b++) {
            zy[b] += z * Yj[b];
          }
        }
        for (int b = 0; b < 6; b++) {
          Zs[6 * a + b] -= zy[b];
        }
        double t = 0;
        for (int j = 0; j < nd; j++) {
          t += Zsn[nd * a + j] * y[j];
        }
        w[a] += t;
      }
      /* W_lb's rows of the piece: Fcᵀ Ad(g_s⁻¹) */
      double As[36];
      csr_strainAdInv_(d->R + 9 * s, d->x + 3 * s, As);
      for (int j = 0; j < nd; j++) {
        const double g[6] = {Fc[j], Fc[nd + j], Fc[2 * nd + j], Fc[3 * nd + j], Fc[4 * nd + j],
                             Fc[5 * nd + j]};
        csr_strainRows6_(d->WMlb + 6 * (c0 + j), As, 6, g, 6, 0);
      }
    }
    memcpy(Zh, Zs, sizeof Zh);
    memcpy(Ic, Ics, sizeof Ic);
    memcpy(wh, w, sizeof wh);
  }
  /* the hip point moves with the base */
  memcpy(Z, Zh, sizeof Zh);
  memcpy(d->WMbb, Ic, sizeof Ic);
  for (int c = 0; c < 6; c++) {
    Z[7 * c] += m->Ms[c];
    d->WMbb[7 * c] += m->Ms[c];
    rho[c] = h * rb[c] - wh[c];
  }
  /* forward: η_k = y_k - X_k ΔV from V_s = T ΔV + t */
  double T[36], t[6];
  memset(T, 0, sizeof T);
  memset(t, 0, sizeof t);
  for (int c = 0; c < 6; c++) {
    T[7 * c] = 1;
  }
  for (int k = 0; k < m->npiece; k++) {
    const int e = m->pt0[k + 1], c0 = m->dof0[k], nd = m->ndof[k];
    const double* A = Ak[k];
    double Te[36], te[6];
    for (int r = 0; r < 6; r++) {
      csr_strainRows6_(Te + 6 * r, T, 6, A + 6 * r, 6, 0);
      double u = 0;
      for (int c = 0; c < 6; c++) {
        u += A[6 * r + c] * t[c];
      }
      te[r] = u;
    }
    if (nd > 0) {
      const double* Le = d->J + (size_t)e * 6 * n + c0;
      double* X = d->X + (size_t)6 * c0;
      double* y = d->y + c0;
      for (int j = 0; j < nd; j++) {
        const double Yj[6] = {X[6 * j], X[6 * j + 1], X[6 * j + 2], X[6 * j + 3], X[6 * j + 4],
                              X[6 * j + 5]};
        double u = y[j];
        for (int a = 0; a < 6; a++) {
          u -= Yj[a] * t[a];
        }
        y[j] = u;
        csr_strainRows6_(X + 6 * j, T, 6, Yj, 6, 0);
      }
      /* T_e = A T - L_e X_k, t_e = A t + L_e y_k */
      for (int r = 0; r < 6; r++) {
        const double* Lr = Le + (size_t)r * n;
        for (int j = 0; j < nd; j++) {
          for (int c = 0; c < 6; c++) {
            Te[6 * r + c] -= Lr[j] * X[6 * j + c];
          }
          te[r] += Lr[j] * y[j];
        }
      }
    }
    memcpy(T, Te, sizeof T);
    memcpy(t, te, sizeof t);
  }
  for (int a = 0; a < 6; a++) {
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  return 0;
}


void csr_strainArticSolve_(const csrStrainModel* m, csrStrainData* d, double* y, double w[6]) {
  /* from the tip: r_k = v_k - L_eᵀ ŵ, Z_ηη⁻¹ r_k into y's rows, ŵ_s = Aᵀ ŵ + Z_sη Z_ηη⁻¹ r_k */
  double wh[6] = {0, 0, 0, 0, 0, 0};
  for (int k = m->npiece - 1; k >= 0; k--) {
    const int c0 = m->dof0[k], nd = m->ndof[k];
    const double* A = d->artA + 36 * k;
    double ws[6];
    mulT6(A, wh, ws);
    if (nd > 0) {
      const double* L = d->artL + (size_t)6 * c0;
      const double* Zsn = d->artZsn + (size_t)6 * c0;
      double* v = y + c0;
      for (int i = 0; i < nd; i++) {
        double t = v[i];
        for (int r = 0; r < 6; r++) {
          t -= L[nd * r + i] * wh[r];
        }
        v[i] = t;
      }
      csr_strainLuSolve_(d->artLU + (size_t)MAXD * c0, nd, d->artPiv + c0, v);
      for (int a = 0; a < 6; a++) {
        double t = 0;
        for (int j = 0; j < nd; j++) {
          t += Zsn[nd * a + j] * v[j];
        }
        ws[a] += t;
      }
    }
    memcpy(wh, ws, sizeof wh);
  }
  memcpy(w, wh, sizeof wh);
  /* from the hip at ΔV = 0: y_k = Z_ηη⁻¹ r_k - Y_k t, t_e = A t + L_e y_k */
  double t[6] = {0, 0, 0, 0, 0, 0};
  for (int k = 0; k < m->npiece; k++) {
    const int c0 = m->dof0[k], nd = m->ndof[k];
    const double* A = d->artA + 36 * k;
    double te[6];
    mul6(A, t, te);
    if (nd > 0) {
      const double* L = d->artL + (size_t)6 * c0;
      const double* Y = d->artY + (size_t)6 * c0;
      double* v = y + c0;
      for (int j = 0; j < nd; j++) {
        double u = v[j];
        for (int a = 0; a < 6; a++) {
          u -= Y[6 * j + a] * t[a];
        }
        v[j] = u;
      }
      for (int r = 0; r < 6; r++) {
        for (int j = 0; j < nd; j++) {
          te[r] += L[nd * r + j] * v[j];
        }
      }
    }
    memcpy(t, te, sizeof t);
  }
}


/* y += a x over n entries (y and x distinct rows): the multi-column sweeps' one operation */
static inline void axpyN(double* restrict y, double a, const double* restrict x, int n) {
  for (int c = 0; c < n; c++) {
    y[c] += a * x[c];
  }
}


/* o = A x (tr 0) or Aᵀ x (tr 1) on nc columns side by side (x, o: 6 x nc), each entry's six
 * terms in order from +0 (mul6's and mulT6's) */
static void mulCols(const double A[36], int tr, const double* x, double* o, int nc) {
  for (int r = 0; r < 6; r++) {
    double* orow = o + r * nc;
    memset(orow, 0, (size_t)nc * sizeof(double));
    for (int a = 0; a < 6; a++) {
      const double ar = tr ? A[6 * a + r] : A[6 * r + a];
      axpyN(orow, ar, x + a * nc, nc);
    }
  }
}


void csr_strainArticSolveMulti_(const csrStrainModel* m, csrStrainData* d, double* B, int nc,
                                double* work) {
  /* csr_strainArticSolve_ on nc columns side by side (each column's operations in its order):
   * wh, ws / te, t (6 x nc each) in work */
  double* wh = work;
  double* ws = work + 6 * nc;
  const size_t row = (size_t)nc * sizeof(double);
  memset(wh, 0, 6 * row);
  for (int k = m->npiece - 1; k >= 0; k--) {
    const int c0 = m->dof0[k], nd = m->ndof[k];
    const double* A = d->artA + 36 * k;
    mulCols(A, 1, wh, ws, nc);
    if (nd > 0) {
      const double* L = d->artL + (size_t)6 * c0;
      const double* Zsn = d->artZsn + (size_t)6 * c0;
      double* V = B + (size_t)c0 * nc;
      for (int i = 0; i < nd; i++) {
        double* v = V + (size_t)i * nc;
        for (int r = 0; r < 6; r++) {
          axpyN(v, -L[nd * r + i], wh + r * nc, nc); /* v - l w, the same bits */
        }
      }
      csr_strainLuSolveMulti_(d->artLU + (size_t)MAXD * c0, nd, d->artPiv + c0, V, nc);
      double* t = wh; /* wh is read no more on this piece: the sums' scratch */
      for (int a = 0; a < 6; a++) {
        memset(t, 0, row);
        for (int j = 0; j < nd; j++) {
          axpyN(t, Zsn[nd * a + j], V + (size_t)j * nc, nc);
        }
        axpyN(ws + a * nc, 1.0, t, nc);
      }
    }
    memcpy(wh, ws, 6 * row);
  }
  /* from the hip at ΔV = 0 */
  double* t = wh;
  double* te = ws;
  memset(t, 0, 6 * row);
  for (int k = 0; k < m->npiece; k++) {
    const int c0 = m->dof0[k], nd = m->ndof[k];
    const double* A = d->artA + 36 * k;
    mulCols(A, 0, t, te, nc);
    if (nd > 0) {
      const double* L = d->artL + (size_t)6 * c0;
      const double* Y = d->artY + (size_t)6 * c0;
      double* V = B + (size_t)c0 * nc;
      for (int j = 0; j < nd; j++) {
        double* v = V + (size_t)j * nc;
        for (int a = 0; a < 6; a++) {
          axpyN(v, -Y[6 * j + a], t + a * nc, nc);
        }
      }
      for (int r = 0; r < 6; r++) {
        double* o = te + r * nc;
        for (int j = 0; j < nd; j++) {
          axpyN(o, L[nd * r + j], V + (size_t)j * nc, nc);
        }
      }
    }
    memcpy(t, te, 6 * row);
  }
}
