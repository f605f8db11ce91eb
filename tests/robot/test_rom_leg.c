/* test_rom_leg.c: the reduced FE leg's dynamics in the hip's floating frame (robot/rom/
 * robot_rom.h) on a clamped silicone block (2 x 1.5 x 6 mm, 24 Tet10) with a basis built here
 * from the reduced model's own static responses (tip forces and moments, the pressure face):
 * the consistent mass operators against closed forms and a brute-force product with the
 * assembled mass; a free vibration whose frequency is the reduced eigenproblem's; a held base
 * with a tip load settling on the reduced statics (csf_romNewton); the base wrench of a
 * uniformly accelerated and of a steadily spinning base against the closed forms of the
 * momentum balance; a restored state stepping bit for bit as the original. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "fem_assembly.h"
#include "fem_rom.h"
#include "robot_rom.h"

#include "rom_test_block.h"


/* the generalised eigenproblem K φ = ω² M φ (n small): the lowest ω and its φ (M-normalised) */
static double lowestMode(int n, const double* K, const double* M, double* phi) {
  /* L Lᵀ = M; A = L⁻¹ K L⁻ᵀ; A ψ = ω² ψ; φ = L⁻ᵀ ψ */
  double* L = calloc((size_t)n * n, sizeof(double));
  double* A = calloc((size_t)n * n, sizeof(double));
  double* W = calloc((size_t)n * n, sizeof(double));
  double* ev = calloc((size_t)n, sizeof(double));
  double* EV = calloc((size_t)n * n, sizeof(double));
  for (int j = 0; j < n; j++) {
    double s = M[j * n + j];
    for (int k = 0; k < j; k++) {
      s -= L[j * n + k] * L[j * n + k];
    }
    L[j * n + j] = sqrt(s);
    for (int i = j + 1; i < n; i++) {
      double t = M[i * n + j];
      for (int k = 0; k < j; k++) {
        t -= L[i * n + k] * L[j * n + k];
      }
      L[i * n + j] = t / L[j * n + j];
    }
  }
  /* W = L⁻¹ K (forward substitution per column), A = W L⁻ᵀ = (L⁻¹ Wᵀ)ᵀ */
  for (int c = 0; c < n; c++) {
    for (int i = 0; i < n; i++) {
      double t = K[i * n + c];
      for (int k = 0; k < i; k++) {
        t -= L[i * n + k] * W[k * n + c];
      }
      W[i * n + c] = t / L[i * n + i];
    }
  }
  for (int r = 0; r < n; r++) {
    for (int i = 0; i < n; i++) {
      double t = W[r * n + i];
      for (int k = 0; k < i; k++) {
        t -= L[i * n + k] * A[r * n + k];
      }
      A[r * n + i] = t / L[i * n + i];
    }
  }
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < i; j++) {
      const double s = 0.5 * (A[i * n + j] + A[j * n + i]);
      A[i * n + j] = A[j * n + i] = s;
    }
  }
  csu_symEigenN(n, A, ev, EV);
  int lo = 0;
  for (int i = 1; i < n; i++) {
    if (ev[i] < ev[lo]) {
      lo = i;
    }
  }
  /* ψ = column lo of EV; φ = L⁻ᵀ ψ */
  for (int i = n - 1; i >= 0; i--) {
    double t = EV[i * n + lo];
    for (int k = i + 1; k < n; k++) {
      t -= L[k * n + i] * phi[k];
    }
    phi[i] = t / L[i * n + i];
  }
  const double w = sqrt(ev[lo]);
  free(L), free(A), free(W), free(ev), free(EV);
  return w;
}


/* mass, first and second moments against the block's closed forms; T, e_k, Q_k, S_ij against
 * brute-force products with the FE's consistent mass assembled node by node (the operators are
 * sums of its 3 x 3 blocks: checked with the nodal rigid fields and the basis directly) */
static void test_mass_operators_match_closed_forms_and_the_assembled_mass(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  csrRomParams par = csr_romDefaultParams();
  par.rho = RHO;
  csrRomModel* m = csr_romModelCreate(b.rom, &par, NULL, &err);
  CS_ASSERT(m != NULL);
  const double vol = BX * BY * BZ, mass = RHO * vol;
  /* the collapsed Gauss rule is exact for straight Tet10s: round-off */
  CS_EXPECT_NEAR(m->mass, mass, 0, 1e-13);
  CS_EXPECT_NEAR(m->s0[0], mass * BX / 2, 0, 1e-13);
  CS_EXPECT_NEAR(m->s0[1], mass * BY / 2, 0, 1e-13);
  CS_EXPECT_NEAR(m->s0[2], mass * BZ / 2, 0, 1e-13);
  CS_EXPECT_NEAR(m->J0[0], mass * BX * BX / 3, 0, 1e-13);
  CS_EXPECT_NEAR(m->J0[2], mass * BZ * BZ / 3, 0, 1e-13);
  CS_EXPECT_NEAR(m->J0[3], mass * BX * BY / 4, 0, 1e-13);
  CS_EXPECT_NEAR(m->J0[5], mass * BY * BZ / 4, 0, 1e-13);
  /* V^T M v for rigid fields v: a translation along e_i is T[:, i]; a rotation about e_k
   * through the hip, v = e_k x X, is e_k; and a basis vector's own M-product is Mr. Brute
   * force: the scalar mass of the mesh assembled densely from the same element rule is
   * replaced by its exact action on the rigid fields, mass-lumping free: (M 1)_a = ∫ρ N_a. */
  const int n = b.n, nn = b.me->nnode;
  double* Na = calloc((size_t)nn, sizeof(double)); /* ∫ρ N_a */
  double* NaX = calloc((size_t)nn * 3, sizeof(double)); /* ∫ρ N_a x */
  /* the same quadrature as the model (an independent code path: the mass row sums) */
  {
    static const double g[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                0.9305681557970263};
    static const double w[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                0.1739274225687269};
    for (int e = 0; e < b.me->ntet; e++) {
      const int* tv = b.me->tet + 10 * e;
      for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
          for (int l = 0; l < 4; l++) {
            const double xi[3] = {g[i], g[j] * (1 - g[i]), g[l] * (1 - g[i]) * (1 - g[j])};
            const double wt = w[i] * w[j] * w[l] * (1 - g[i]) * (1 - g[i]) * (1 - g[j]);
            double N[10], dN[30], J[9] = {0}, x[3] = {0};
            csf_tet10Shape(xi, N, dN);
            for (int a = 0; a < 10; a++) {
              for (int r = 0; r < 3; r++) {
                x[r] += N[a] * b.me->x[3 * tv[a] + r];
                for (int c = 0; c < 3; c++) {
                  J[3 * r + c] += b.me->x[3 * tv[a] + r] * dN[3 * a + c];
                }
              }
            }
            const double det = J[0] * (J[4] * J[8] - J[5] * J[7]) -
                               J[1] * (J[3] * J[8] - J[5] * J[6]) +
                               J[2] * (J[3] * J[7] - J[4] * J[6]);
            for (int a = 0; a < 10; a++) {
              Na[tv[a]] += RHO * wt * det * N[a];
              for (int r = 0; r < 3; r++) {
                NaX[3 * tv[a] + r] += RHO * wt * det * N[a] * x[r];
              }
            }
          }
        }
      }
    }
  }
  double worst_T = 0, worst_e = 0, scale_T = 0, scale_e = 0, worst_d = 0, scale_d = 0;
  static const int pi_[6] = {0, 1, 2, 0, 0, 1}, pj_[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < n; k++) {
    double T[3] = {0, 0, 0}, ek[3] = {0, 0, 0}, dij[6] = {0, 0, 0, 0, 0, 0};
    for (int a = 0; a < nn; a++) {
      const double* X = NaX + 3 * a;
      for (int i = 0; i < 3; i++) {
        T[i] += b.V[(size_t)(3 * a + i) * n + k] * Na[a];
      }
      /* e_k component r: Σ_a V_a . (e_r x ∫ρ N_a x) */
      const double* Va0 = b.V + (size_t)(3 * a) * n + k;
      const double va[3] = {Va0[0], Va0[n], Va0[2 * n]};
      const double ex[3][3] = {{0, -X[2], X[1]}, {X[2], 0, -X[0]}, {-X[1], X[0], 0}};
      for (int r = 0; r < 3; r++) {
        ek[r] += va[0] * ex[r][0] + va[1] * ex[r][1] + va[2] * ex[r][2];
      }
      /* d_ij: Σ_a V_a . (D_ij ∫ρ N_a x), D_ij y = (y_j e_i + y_i e_j) / 2 */
      for (int c = 0; c < 6; c++) {
        const int i = pi_[c], j = pj_[c];
        dij[c] += 0.5 * (va[i] * X[j] + va[j] * X[i]);
      }
    }
    for (int c = 0; c < 6; c++) {
      worst_d = fmax(worst_d, fabs(dij[c] - m->d[(size_t)c * n + k]));
      scale_d = fmax(scale_d, fabs(dij[c]));
    }
    for (int i = 0; i < 3; i++) {
      worst_T = fmax(worst_T, fabs(T[i] - m->T[3 * k + i]));
      scale_T = fmax(scale_T, fabs(T[i]));
      worst_e = fmax(worst_e, fabs(ek[i] - m->e[(size_t)i * n + k]));
      scale_e = fmax(scale_e, fabs(ek[i]));
    }
  }
  printf("  mass %.6g t; T %.2e of %.2e, e %.2e of %.2e, d %.2e of %.2e\n", m->mass, worst_T,
         scale_T, worst_e, scale_e, worst_d, scale_d);
  /* the same sums in another order: round-off */
  CS_EXPECT(worst_T <= 1e-12 * scale_T);
  CS_EXPECT(worst_e <= 1e-12 * scale_e);
  CS_EXPECT(worst_d <= 1e-12 * scale_d);
  /* Q_k skew, S_ij and Mr symmetric, Mr = S_00 + S_11 + S_22 */
  double asym = 0, trace_gap = 0, mr = 0;
  const size_t nq = (size_t)n * n;
  for (int k = 0; k < n; k++) {
    for (int l = 0; l < n; l++) {
      const size_t kl = (size_t)k * n + l, lk = (size_t)l * n + k;
      for (int i = 0; i < 3; i++) {
        asym = fmax(asym, fabs(m->Q[i * nq + kl] + m->Q[i * nq + lk]));
      }
      for (int i = 0; i < 6; i++) {
        asym = fmax(asym, fabs(m->S[i * nq + kl] - m->S[i * nq + lk]));
      }
      trace_gap = fmax(trace_gap, fabs(m->S[kl] + m->S[nq + kl] + m->S[2 * nq + kl] - m->Mr[kl]));
      mr = fmax(mr, fabs(m->Mr[kl]));
    }
  }
  CS_EXPECT(asym <= 1e-13 * mr);
  CS_EXPECT(trace_gap <= 1e-13 * mr);
  free(Na), free(NaX);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* the reduced tangent at rest (N/mm per unit q) */
static void restTangent(const Block* b, double* K) {
  csError err = {0};
  csfRomData* fd = csf_romDataCreate(b->rom, &err);
  csf_romDataReset(b->rom, fd);
  fd->sync = 1;
  csfRomLoad ld;
  memset(&ld, 0, sizeof ld);
  CS_ASSERT(csf_romEvaluate(b->rom, fd, &ld, 1) == 0);
  memcpy(K, fd->K, (size_t)b->n * b->n * sizeof(double));
  csf_romDataDestroy(fd);
}


/* the block's parameters with the lowest mode critically damped, ζ_1 = τ ω_1 / 2 = 1 (the
 * others over-damped: C = τ K_r(0)), and tolerances tight enough for the settling tests; *w1
 * the lowest reduced eigenfrequency (rad/s) */
static csrRomParams criticallyDamped(const Block* b, double* w1) {
  csError err = {0};
  const int n = b->n;
  double* K = malloc((size_t)n * n * sizeof(double));
  double* phi = malloc((size_t)n * sizeof(double));
  csrRomParams par = csr_romDefaultParams();
  par.rho = RHO;
  csrRomModel* m0 = csr_romModelCreate(b->rom, &par, NULL, &err);
  CS_ASSERT(m0 != NULL);
  restTangent(b, K);
  *w1 = lowestMode(n, K, m0->Mr, phi);
  csr_romModelDestroy(m0);
  par.damping_time = 2 / *w1;
  par.rtol = 1e-9;
  par.atol_u = 1e-12;
  free(K), free(phi);
  return par;
}


/* undamped, the base still, released from a small displacement along the lowest mode of
 * K_r(0) φ = ω² M_r φ: the modal coordinate φᵀ M_r q oscillates at ω. The amplitude (1e-5 of
 * the block's size) keeps the nonlinear terms (relative O(amplitude)) below the integrator's
 * error; the period is timed between zero crossings found by cubic Hermite interpolation of
 * the modal coordinate and its rate on 100 macro steps per period. */
static void test_free_vibration_has_the_reduced_eigenfrequency(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  csrRomParams par = csr_romDefaultParams();
  par.rho = RHO;
  par.damping_time = 0;
  par.rtol = 1e-10;
  par.atol_u = 1e-14;
  csrRomModel* m = csr_romModelCreate(b.rom, &par, NULL, &err);
  CS_ASSERT(m != NULL);
  const int n = b.n;
  double* K = malloc((size_t)n * n * sizeof(double));
  double* phi = malloc((size_t)n * sizeof(double));
  restTangent(&b, K);
  const double w1 = lowestMode(n, K, m->Mr, phi);
  const double T1 = 2 * M_PI / w1;
  csrRomData* d = csr_romDataCreate(m, &err);
  CS_ASSERT(d != NULL);
  const int ns = csr_romStateSize(m);
  double* x = malloc((size_t)ns * sizeof(double));
  csr_romGetState(m, d, x);
  double pmax = 0;
  for (int k = 0; k < n; k++) {
    pmax = fmax(pmax, fabs(phi[k]));
  }
  for (int k = 0; k < n; k++) {
    x[1 + k] = 1e-5 * BX * phi[k] / pmax;
  }
  CS_ASSERT(csr_romSetState(m, d, x) == 0);
  csrBaseState b0 = restBase();
  const double H = T1 / 100;
  double t = 0, prev = 0, prevd = 0, first = NAN, last = NAN;
  int crossings = 0;
  for (int s = 0; s <= 400; s++) {
    const double* q = csr_romQ(d);
    const double* qd = csr_romQdot(d);
    double a = 0, ad = 0; /* φᵀ M q and its rate */
    for (int k = 0; k < n; k++) {
      for (int l = 0; l < n; l++) {
        a += phi[k] * m->Mr[k * n + l] * q[l];
        ad += phi[k] * m->Mr[k * n + l] * qd[l];
      }
    }
    if (s > 0 && prev > 0 && a <= 0) {
      /* the root of the cubic Hermite on [t - H, t] by bisection */
      double lo = 0, hi = 1;
      for (int it = 0; it < 60; it++) {
        const double u = 0.5 * (lo + hi), u2 = u * u, u3 = u2 * u;
        const double v = (2 * u3 - 3 * u2 + 1) * prev + (u3 - 2 * u2 + u) * H * prevd +
                         (-2 * u3 + 3 * u2) * a + (u3 - u2) * H * ad;
        if (v > 0) {
          lo = u;
        } else {
          hi = u;
        }
      }
      const double tc = t - H + 0.5 * (lo + hi) * H;
      if (crossings == 0) {
        first = tc;
      }
      last = tc;
      crossings++;
    }
    prev = a;
    prevd = ad;
    if (s < 400) {
      CS_ASSERT(csr_romAdvance(m, d, t, H, &b0, &b0, NULL, &err) == 0);
      t += H;
    }
  }
  const double T_meas = (last - first) / (crossings - 1);
  printf("  lowest reduced mode %.6g Hz; measured %.9g Hz over %d periods (%+.2e)\n",
         w1 / (2 * M_PI), 1 / T_meas, crossings - 1, T_meas / T1 - 1);
  CS_EXPECT(crossings >= 3);
  /* rtol 1e-10 over 4 periods, and the Hermite interpolation's O(H^4) of a sine sampled 100
   * times per period (2e-7 of the period): 1e-6 */
  CS_EXPECT_NEAR(T_meas, T1, 0, 1e-6);
  free(K), free(phi), free(x);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* the base held still, a tip force (0.02 N across, large enough to rotate the tip by a few
 * degrees) switched on at t = 0 and the leg damped: it settles on the reduced statics of the
 * same load (csf_romNewton from rest) */
static void test_held_base_and_tip_load_settle_on_the_reduced_statics(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  const int n = b.n;
  double w1;
  csrRomParams par = criticallyDamped(&b, &w1);
  csrRomModel* m = csr_romModelCreate(b.rom, &par, NULL, &err);
  CS_ASSERT(m != NULL);
  double* f = calloc((size_t)3 * b.me->nnode, sizeof(double));
  int ntip = 0;
  for (int i = 0; i < b.me->nnode; i++) {
    ntip += fabs(b.me->x[3 * i + 2] - BZ) < 1e-9;
  }
  for (int i = 0; i < b.me->nnode; i++) {
    if (fabs(b.me->x[3 * i + 2] - BZ) < 1e-9) {
      f[3 * i] = 0.02 / ntip;
      f[3 * i + 1] = 0.01 / ntip;
    }
  }
  double* fr = malloc((size_t)n * sizeof(double));
  csf_romProject(b.rom, f, fr);
  /* the statics */
  csfRomData* sd = csf_romDataCreate(b.rom, &err);
  csf_romDataReset(b.rom, sd);
  csfRomLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.f_dead = fr;
  csfRomNewtonOptions no = csf_romNewtonDefault();
  no.rtol = 1e-13;
  no.atol = 0;
  CS_ASSERT(csf_romNewton(b.rom, sd, &ld, &no, NULL, &err) == CS_OK);
  /* the dynamics: 30 periods of the lowest mode */
  csrRomData* d = csr_romDataCreate(m, &err);
  CS_ASSERT(d != NULL);
  csr_romSetDeadLoad(m, d, fr);
  csrBaseState b0 = restBase();
  const double T1 = 2 * M_PI / w1, H = T1 / 20;
  double t = 0;
  for (int s = 0; s < 600; s++) {
    CS_ASSERT(csr_romAdvance(m, d, t, H, &b0, &b0, NULL, &err) == 0);
    t += H;
  }
  double gap = 0, scale = 0;
  const double* q = csr_romQ(d);
  for (int k = 0; k < n; k++) {
    gap = fmax(gap, fabs(q[k] - sd->q[k]));
    scale = fmax(scale, fabs(sd->q[k]));
  }
  long st, nr, nj, nre;
  csr_romStats(d, &st, &nr, &nj, &nre);
  printf("  statics |q| %.4g; after 30 periods |q - q_static| %.2e (%ld steps, %ld rhs, %ld "
         "jacobians, %ld restarts)\n", scale, gap, st, nr, nj, nre);
  /* critically damped: the transient is below e^{-ω t} (1 + ω t) ~ 1e-79 after 30 periods;
   * what remains is CVODE's rtol 1e-9 */
  CS_EXPECT(gap <= 1e-7 * scale);
  free(f), free(fr);
  csf_romDataDestroy(sd);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* pressure on the chamber face and gravity together, the hip turned (e3 along world -y): the
 * damped leg settles on the reduced statics csf_romNewton finds with the FE's own body-force
 * rule for gravity (fem_rom.h csfRom.G; exact on straight Tet10s, as the consistent mass here)
 * and the same face pressures: the chamber map, the follower load and the frame's gravity
 * through T are those of the statics */
static void test_pressure_and_gravity_settle_on_the_reduced_statics(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  const int n = b.n;
  double w1;
  csrRomParams par = criticallyDamped(&b, &w1);
  par.gravity[1] = -9810.0 * 1000; /* 1000 g: a deflection comparable to the pressure's */
  int* ch = chamberFaces(&b);
  csrRomModel* m = csr_romModelCreate(b.rom, &par, ch, &err);
  CS_ASSERT(m != NULL);
  const double P = 0.004; /* MPa on the face x = BX */
  /* the hip frame: e1 = x, e2 = z, e3 = -y (world) */
  csrBaseState b0 = restBase();
  const double R[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(b0.R, R, sizeof R);
  /* the statics: gravity in the hip frame, R^T g */
  double gb[3];
  csu_mulMatTVec3(gb, R, par.gravity);
  double* face_p = calloc((size_t)b.me->nface, sizeof(double));
  for (int f = 0; f < b.me->nface; f++) {
    face_p[f] = ch[f] == 0 ? P : 0.0;
  }
  csfRomData* sd = csf_romDataCreate(b.rom, &err);
  csf_romDataReset(b.rom, sd);
  csfRomLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.face_p = face_p;
  memcpy(ld.gravity, gb, sizeof gb);
  csfRomNewtonOptions no = csf_romNewtonDefault();
  no.rtol = 1e-13;
  no.atol = 0;
  CS_ASSERT(csf_romNewton(b.rom, sd, &ld, &no, NULL, &err) == CS_OK);
  csrRomData* d = csr_romDataCreate(m, &err);
  CS_ASSERT(d != NULL);
  csr_romReset(m, d, 0.0, &b0);
  double p0[12] = {0}, p1[12] = {0};
  p0[0] = p1[0] = P;
  const double T1 = 2 * M_PI / w1, H = T1 / 20;
  double t = 0;
  for (int s = 0; s < 600; s++) {
    csr_romActuate(d, t, p0, t + H, p1);
    CS_ASSERT(csr_romAdvance(m, d, t, H, &b0, &b0, NULL, &err) == 0);
    t += H;
  }
  double gap = 0, scale = 0;
  const double* q = csr_romQ(d);
  for (int k = 0; k < n; k++) {
    gap = fmax(gap, fabs(q[k] - sd->q[k]));
    scale = fmax(scale, fabs(sd->q[k]));
  }
  printf("  statics |q| %.4g; after 30 periods |q - q_static| %.2e\n", scale, gap);
  /* as the tip load's case: CVODE's rtol 1e-9; the two gravity rules agree to round-off on
   * straight elements */
  CS_EXPECT(gap <= 1e-7 * scale);
  CS_EXPECT(scale > 0.1); /* a load that deforms the block */
  free(face_p), free(ch);
  csf_romDataDestroy(sd);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* the deformed first mass moment s(q) = s0 + Tᵀ q (t mm, hip frame) */
static void deformedMoment(const csrRomModel* m, const double* q, double s[3]) {
  memcpy(s, m->s0, 3 * sizeof(double));
  for (int k = 0; k < m->n; k++) {
    for (int i = 0; i < 3; i++) {
      s[i] += m->T[3 * k + i] * q[k];
    }
  }
}


/* the averaged base wrench w against f_ref, m_ref, each within rel of its magnitude */
static void expectWrench(const char* what, const csrWrench* w, const double f_ref[3],
                         const double m_ref[3], double rel) {
  const double fs = csu_norm3(f_ref), ms = csu_norm3(m_ref);
  printf("  %s: f (%.6g %.6g %.6g) vs (%.6g %.6g %.6g) N; m_h (%.5g %.5g %.5g) vs (%.5g %.5g "
         "%.5g) N mm\n", what, w->f[0], w->f[1], w->f[2], f_ref[0], f_ref[1], f_ref[2], w->m[0],
         w->m[1], w->m[2], m_ref[0], m_ref[1], m_ref[2]);
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(w->f[k], f_ref[k], rel * fs, 0);
    CS_EXPECT_NEAR(w->m[k], m_ref[k], rel * ms, 0);
  }
}


/* the hip accelerated uniformly along a (with gravity g): once the damped leg has settled in
 * the accelerated frame it moves rigidly with the hip, P = m v_h, and the momentum balance
 * gives the averaged base wrench in closed form, f = m (g - a) and m_h = R s(q) x (g - a) (s the
 * deformed first mass moment). */
static void test_uniformly_accelerated_base_wrench_is_m_times_g_minus_a(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  double w1;
  csrRomParams par = criticallyDamped(&b, &w1);
  par.gravity[1] = -9810.0;
  csrRomModel* m = csr_romModelCreate(b.rom, &par, NULL, &err);
  CS_ASSERT(m != NULL);
  csrRomData* d = csr_romDataCreate(m, &err);
  const double a[3] = {3000.0, 0, 1000.0}; /* mm/s^2 */
  const double T1 = 2 * M_PI / w1, H = T1 / 20;
  csrBaseState b0 = restBase(), b1;
  double t = 0;
  csrWrench w = {{0}, {0}};
  for (int s = 0; s < 600; s++) {
    b1 = b0;
    for (int k = 0; k < 3; k++) {
      b1.x[k] = b0.x[k] + b0.v[k] * H + 0.5 * a[k] * H * H;
      b1.v[k] = b0.v[k] + a[k] * H;
    }
    CS_ASSERT(csr_romAdvance(m, d, t, H, &b0, &b1, &w, &err) == 0);
    b0 = b1;
    t += H;
  }
  double ga[3], f_ref[3], s[3], m_ref[3];
  for (int k = 0; k < 3; k++) {
    ga[k] = par.gravity[k] - a[k];
    f_ref[k] = m->mass * ga[k];
  }
  deformedMoment(m, csr_romQ(d), s);
  csu_cross3(m_ref, s, ga);
  /* the transient has decayed (1e-79); the impulse and ΔP/H carry CVODE's rtol 1e-9 on
   * states of |P| = m |v_h| growing to 600 H a: 1e-6 of the weight */
  expectWrench("uniform acceleration", &w, f_ref, m_ref, 1e-6);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* the hip spinning steadily about the world's y axis (across the block, through the hip): once
 * settled, the leg turns rigidly with the frame, so P = R (ω × s(q)) and the averaged wrench is
 * f = -ω_w × (ω_w × R s(q)) exactly per unit time (the centripetal force of the mass centre),
 * and m_h = -ω_w × L_h. The steady state exists only if the centrifugal and Coriolis operators
 * of the equations of motion (Q_k, S_ij) are those of the momentum (the same ones, here checked
 * through a frame whose rotation CVODE follows in the right-hand side). */
static void test_steadily_spinning_base_wrench_is_the_centripetal_force(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  double w1;
  csrRomParams par = criticallyDamped(&b, &w1);
  csrRomModel* m = csr_romModelCreate(b.rom, &par, NULL, &err);
  CS_ASSERT(m != NULL);
  csrRomData* d = csr_romDataCreate(m, &err);
  const double Om = 0.2 * w1; /* rad/s: well below the first mode */
  const double T1 = 2 * M_PI / w1, H = T1 / 20;
  /* the spin starts at once; the leg settles from its start-up transient */
  csrBaseState b0 = restBase(), b1;
  b0.w[1] = Om;
  csr_romReset(m, d, 0.0, &b0);
  double t = 0;
  csrWrench w = {{0}, {0}};
  for (int s = 0; s < 600; s++) {
    b1 = b0;
    const double ax[3] = {0, 1, 0};
    csu_axisAngleToMat3(b1.R, ax, Om * (t + H));
    CS_ASSERT(csr_romAdvance(m, d, t, H, &b0, &b1, &w, &err) == 0);
    b0 = b1;
    t += H;
  }
  double P[3], L[3], s[3], Rs[3], ws[3], f_ref[3], m_ref[3];
  csr_romMomentum(m, d, P, L);
  deformedMoment(m, csr_romQ(d), s);
  csu_mulMatVec3(Rs, b0.R, s);
  csu_cross3(ws, b0.w, Rs);
  csu_cross3(f_ref, b0.w, ws);
  csu_scale3(f_ref, f_ref, -1.0);
  csu_cross3(m_ref, b0.w, L);
  csu_scale3(m_ref, m_ref, -1.0);
  /* the steady deformation against the reduced statics of the centrifugal load, solved here by
   * Newton on r(q) + Σ c_ij (d_ij + S_ij q) = 0 with the operators checked on their own
   * (d_ij: test_mass_operators...; S_ij symmetric, Σ S_ii = M_r): the equations of motion's
   * frame terms are those, the Coriolis term vanishes in the steady state. (The linear statics
   * K_r(0) q = ... is 0.5 % off at 0.05 ω_1 and 25 % at 0.2 ω_1: the centrifugal tension's
   * geometric stiffening is not small here.) */
  {
    csfRomData* sd = csf_romDataCreate(b.rom, &err);
    csf_romDataReset(b.rom, sd);
    sd->sync = 1;
    csfRomLoad ld;
    memset(&ld, 0, sizeof ld);
    double A[36], g[6], wb[3], c[6];
    csu_mulMatTVec3(wb, b0.R, b0.w);
    const double w2 = csu_dot3(wb, wb);
    c[0] = wb[0] * wb[0] - w2, c[1] = wb[1] * wb[1] - w2, c[2] = wb[2] * wb[2] - w2;
    c[3] = 2 * wb[0] * wb[1], c[4] = 2 * wb[0] * wb[2], c[5] = 2 * wb[1] * wb[2];
    const int nb = b.n;
    double gn = 0;
    for (int it = 0; it < 30; it++) {
      CS_ASSERT(csf_romEvaluate(b.rom, sd, &ld, 1) == 0);
      gn = 0;
      for (int k = 0; k < nb; k++) {
        g[k] = sd->r[k];
        for (int i = 0; i < 6; i++) {
          const double* Sk = m->S + (size_t)i * nb * nb + (size_t)k * nb;
          g[k] += c[i] * m->d[(size_t)i * nb + k];
          for (int l = 0; l < nb; l++) {
            g[k] += c[i] * Sk[l] * sd->q[l];
          }
        }
        gn = fmax(gn, fabs(g[k]));
        for (int l = 0; l < nb; l++) {
          A[k * nb + l] = sd->K[k * nb + l];
          for (int i = 0; i < 6; i++) {
            A[k * nb + l] += c[i] * m->S[(size_t)i * nb * nb + (size_t)k * nb + l];
          }
        }
      }
      denseSolve(nb, A, g);
      for (int k = 0; k < nb; k++) {
        sd->q[k] -= g[k];
      }
    }
    const double* q = csr_romQ(d);
    double gap = 0, qs = 0;
    for (int k = 0; k < nb; k++) {
      gap = fmax(gap, fabs(q[k] - sd->q[k]));
      qs = fmax(qs, fabs(sd->q[k]));
    }
    printf("  steady |q| %.3g; against the reduced statics of the centrifugal load %.2e "
           "(Newton's last |g| %.1e N)\n", qs, gap, gn);
    /* the transient has decayed; CVODE's rtol 1e-9 */
    CS_EXPECT(gap <= 1e-7 * qs);
    csf_romDataDestroy(sd);
  }
  /* the wrench turns with the frame: its average over the last step is the end value turned
   * back through the step, (1/H) ∫ R_y(Ω (τ - H)) dτ applied to it (midpoint rule, 2000 points:
   * 1e-8 relative) */
  double f_avg[3] = {0, 0, 0}, m_avg[3] = {0, 0, 0};
  for (int i = 0; i < 2000; i++) {
    const double ax[3] = {0, 1, 0};
    double Rb[9], fa[3], ma[3];
    csu_axisAngleToMat3(Rb, ax, -Om * H * (i + 0.5) / 2000);
    csu_mulMatVec3(fa, Rb, f_ref);
    csu_mulMatVec3(ma, Rb, m_ref);
    csu_addScl3(f_avg, f_avg, fa, 1.0 / 2000);
    csu_addScl3(m_avg, m_avg, ma, 1.0 / 2000);
  }
  memcpy(f_ref, f_avg, sizeof f_ref);
  memcpy(m_ref, m_avg, sizeof m_ref);
  /* a rotation about a fixed axis is exact in the Hermite frame motion (robot_rom.h); the
   * transient has decayed; CVODE's rtol 1e-9 on the momenta and the impulse: 1e-6 */
  printf("  spin %.4g rad/s\n", Om);
  expectWrench("steady spin", &w, f_ref, m_ref, 1e-6);
  csr_romDataDestroy(d);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


/* a state saved mid-motion (pressurised, base moving) and restored into another data and into
 * the same steps bit for bit alike, and as the original run to its integration error */
static void test_restored_state_steps_bit_for_bit(void) {
  Block b;
  blockCreate(&b, 4);
  csError err = {0};
  csrRomParams par = csr_romDefaultParams();
  par.rho = RHO;
  par.gravity[1] = -9810.0;
  par.rtol = 1e-9; /* tight: the restored run is compared with the original below */
  par.atol_u = 1e-10;
  int* ch = chamberFaces(&b);
  csrRomModel* m = csr_romModelCreate(b.rom, &par, ch, &err);
  CS_ASSERT(m != NULL);
  csrRomData* d = csr_romDataCreate(m, &err);
  csrRomData* e = csr_romDataCreate(m, &err);
  const double H = 1e-3;
  double p0[12] = {0}, p1[12] = {0};
  csrBaseState b0 = restBase(), b1 = b0;
  double t = 0;
  const int ns = csr_romStateSize(m);
  double* xs = malloc((size_t)ns * sizeof(double));
  double* xa = malloc((size_t)ns * sizeof(double));
  double* xb = malloc((size_t)ns * sizeof(double));
  csrWrench wa = {{0}, {0}}, wb = {{0}, {0}};
  for (int s = 0; s < 10; s++) {
    p1[0] = 0.002 * (s + 1);
    csr_romActuate(d, t, p0, t + H, p1);
    b1.x[0] = b0.x[0] + 0.5 * H;
    b1.v[0] = 500.0;
    const int rc_ = csr_romAdvance(m, d, t, H, &b0, &b1, &wa, &err);
    if (rc_ != 0) {
      fprintf(stderr, "%s\n", err.msg);
    }
    CS_ASSERT(rc_ == 0);
    if (s == 4) {
      csr_romGetState(m, d, xs);
    }
    b0 = b1;
    p0[0] = p1[0];
    t += H;
  }
  double* xo = malloc((size_t)ns * sizeof(double));
  csrWrench wo = wa;
  csr_romGetState(m, d, xo);
  /* again from the saved state (t = 5 H) in e, and again in d */
  for (int pass = 0; pass < 2; pass++) {
    csrRomData* x = pass == 0 ? e : d;
    CS_ASSERT(csr_romSetState(m, x, xs) == 0);
    double tt = 5 * H;
    csrBaseState c0 = restBase(), c1;
    c0.x[0] = 5 * 0.5 * H;
    c0.v[0] = 500.0;
    double q0[12] = {0}, q1[12] = {0};
    q0[0] = 0.002 * 5;
    for (int s = 5; s < 10; s++) {
      c1 = c0;
      q1[0] = 0.002 * (s + 1);
      csr_romActuate(x, tt, q0, tt + H, q1);
      c1.x[0] = c0.x[0] + 0.5 * H;
      CS_ASSERT(csr_romAdvance(m, x, tt, H, &c0, &c1, pass == 0 ? &wa : &wb, &err) == 0);
      c0 = c1;
      q0[0] = q1[0];
      tt += H;
    }
    csr_romGetState(m, x, pass == 0 ? xa : xb);
  }
  CS_EXPECT(memcmp(xa, xb, (size_t)ns * sizeof(double)) == 0);
  CS_EXPECT(memcmp(&wa, &wb, sizeof wa) == 0);
  /* the original run carried CVODE's history on where the restores restarted it: the same
   * states to the integration error (rtol 1e-9, atol 1e-10 mm and 1e-7 mm/s, accumulated over
   * five steps of the first-order restart against the running BDF): 1e-4 of the largest
   * entry leaves room */
  double dq = 0, qs = 0;
  for (int k = 1; k <= 2 * b.n; k++) {
    dq = fmax(dq, fabs(xa[k] - xo[k]));
    qs = fmax(qs, fabs(xo[k]));
  }
  printf("  restored against the original run: |dy| %.2e of %.2e; wrench %.3g vs %.3g N\n", dq,
         qs, wa.f[1], wo.f[1]);
  CS_EXPECT(dq <= 1e-4 * qs);
  /* a non-finite state is refused and changes nothing */
  xs[1] = NAN;
  CS_EXPECT(csr_romSetState(m, e, xs) < 0);
  csr_romGetState(m, e, xb);
  CS_EXPECT(memcmp(xa, xb, (size_t)ns * sizeof(double)) == 0);
  free(xs), free(xa), free(xb), free(xo), free(ch);
  csr_romDataDestroy(d);
  csr_romDataDestroy(e);
  csr_romModelDestroy(m);
  blockDestroy(&b);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_mass_operators_match_closed_forms_and_the_assembled_mass);
  CS_RUN(test_free_vibration_has_the_reduced_eigenfrequency);
  CS_RUN(test_held_base_and_tip_load_settle_on_the_reduced_statics);
  CS_RUN(test_pressure_and_gravity_settle_on_the_reduced_statics);
  CS_RUN(test_uniformly_accelerated_base_wrench_is_m_times_g_minus_a);
  CS_RUN(test_steadily_spinning_base_wrench_is_the_centripetal_force);
  CS_RUN(test_restored_state_steps_bit_for_bit);
  return cs_testSummary();
}
