/* test_fem_rom.c: the reduced-order FE model (fem_rom.h) against the full FE on small box
 * meshes: the reduced residual and tangent equal V^T R and V^T K V of the FE's assembly and the
 * tangent equals the residual's finite differences (Tet10 mixed bodies, a follower pressure
 * face, an embedded fibre, gravity, a dead load); with the full basis (every free dof) and with
 * a basis of two FE snapshots the reduced Newton reproduces the FE's equilibria to the Newton
 * tolerance; every element kept at weight 1, in any order, is the unreduced model to round-off. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_assembly.h"
#include "fem_element.h"
#include "fem_rom.h"
#include "fem_test_util.h"
#include "rom_test_util.h"

/* the blocks' end pressure, MPa (bends the 6 mm block by about 1.5 mm: large rotations) */
#define P_BOX 0.006

/* r and K of the rom against V^T R, V^T K V of the FE's assembly at u = V q, and K against
 * central differences of r */
static void test_reduced_residual_and_tangent_match_the_fe_and_finite_differences(void) {
  RtBox b;
  rtBoxCreate(&b, 2, 3.0, 50.0, 1, 1); /* moderate kappa: a well-conditioned FD check (as
                                * test_fem_element) */
  const csfModel* m = b.m;
  const int nd = m->ndof, n = 5;
  double* V = calloc((size_t)nd * n, sizeof(double));
  srand(11);
  for (int i = 0; i < nd; i++) {
    if (m->fixed[i]) {
      continue;
    }
    const double* X = b.me->x + 3 * (i / 3);
    V[(size_t)i * n] = (i % 3 == 0) ? 0.1 * X[0] : 0.0; /* stretches the fibre along x */
    for (int j = 1; j < n; j++) {
      V[(size_t)i * n + j] = 0.05 * ((double)rand() / RAND_MAX - 0.5) * X[2];
    }
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  CS_EXPECT(r != NULL);
  csfRomData* rd = csf_romDataCreate(r, &err);
  rd->sync = 1; /* the exact derivative: theta = v/V, S = S(E) */
  const double q[5] = {1.0, 0.7, -0.4, 0.3, 0.9};
  memcpy(rd->q, q, sizeof q);
  const double load = 0.05; /* MPa */
  double* fp = rtFacePressure(m, load);
  double fdead[5] = {0.01, -0.02, 0.0, 0.005, 0.0};
  csfRomLoad ld = {fp, {0, -9810.0, 0}, fdead};
  CS_EXPECT(csf_romEvaluate(r, rd, &ld, 1) == 0);
  /* the FE at u = V q, its dilatation and fibre states synced (exact tangent) */
  csf_romExpand(r, q, b.d->u);
  b.d->load = load;
  csf_dataSyncVolume(m, b.d);
  CS_EXPECT(csf_assemble(m, b.d, load, 1) == 0);
  double* KV = malloc((size_t)nd * n * sizeof(double));
  double* col = malloc((size_t)nd * sizeof(double));
  double* y = malloc((size_t)nd * sizeof(double));
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < nd; i++) {
      col[i] = V[(size_t)i * n + j];
    }
    csf_tangentApply(m, b.d, col, y);
    for (int i = 0; i < nd; i++) {
      KV[(size_t)i * n + j] = y[i];
    }
  }
  double rfe[5], emr = 0, mr = 0, emk = 0, mk = 0;
  csf_romProject(r, b.d->r, rfe);
  for (int j = 0; j < n; j++) {
    rfe[j] -= fdead[j]; /* the FE model has no dead load here */
    emr = fmax(emr, fabs(rfe[j] - rd->r[j]));
    mr = fmax(mr, fabs(rd->r[j]));
    for (int k = 0; k < n; k++) {
      double s = 0;
      for (int i = 0; i < nd; i++) {
        s += V[(size_t)i * n + j] * KV[(size_t)i * n + k];
      }
      emk = fmax(emk, fabs(s - rd->K[j * n + k]));
      mk = fmax(mk, fabs(rd->K[j * n + k]));
    }
  }
  printf("  rom vs FE assembly: max |r - V^T R| = %.2e of %.2e N, max |K - V^T K V| = %.2e of "
         "%.2e N/mm\n", emr, mr, emk, mk);
  /* the same kernels summed in another order: round-off (1e-12 relative leaves 4 digits) */
  CS_EXPECT_NEAR(emr / mr, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(emk / mk, 0.0, 1e-12, 0);
  /* central differences of r */
  const double h = 1e-6; /* truncation ~h^2 |r'''|, round-off ~1e-16 |r| / h */
  double* rp = malloc(n * sizeof(double));
  double* K = malloc((size_t)n * n * sizeof(double));
  memcpy(K, rd->K, (size_t)n * n * sizeof(double));
  double efd = 0, asym = 0;
  for (int j = 0; j < n; j++) {
    rd->q[j] = q[j] + h;
    csf_romEvaluate(r, rd, &ld, 0);
    memcpy(rp, rd->r, n * sizeof(double));
    rd->q[j] = q[j] - h;
    csf_romEvaluate(r, rd, &ld, 0);
    rd->q[j] = q[j];
    for (int i = 0; i < n; i++) {
      efd = fmax(efd, fabs((rp[i] - rd->r[i]) / (2 * h) - K[i * n + j]));
      asym = fmax(asym, fabs(K[i * n + j] - K[j * n + i]));
    }
  }
  printf("  rom tangent vs central differences: max |K - K_fd| / max |K| = %.2e; asymmetry "
         "%.2e (an open pressure face: not symmetric)\n", efd / mk, asym / mk);
  /* measured ~1e-9; 1e-6 as test_fem_element: a missing term is 1e-2 or more */
  CS_EXPECT_NEAR(efd / mk, 0.0, 1e-6, 0);
  /* the pressurised face set in closed form (a cubic volume in q): the same r and K */
  int* fch = malloc((size_t)b.me->nface * sizeof(int));
  for (int f = 0; f < b.me->nface; f++) {
    fch[f] = b.me->face_tag[f] == 2 ? 0 : -1;
  }
  double r_el[5], K_el[25];
  CS_EXPECT(csf_romEvaluate(r, rd, &ld, 1) == 0);
  memcpy(r_el, rd->r, sizeof r_el);
  memcpy(K_el, rd->K, sizeof K_el);
  CS_EXPECT(csf_romChamberTensors(r, 1, fch, &err) == CS_OK);
  CS_EXPECT(csf_romEvaluate(r, rd, &ld, 1) == 0);
  double etr = 0, etk = 0;
  for (int i = 0; i < n; i++) {
    etr = fmax(etr, fabs(rd->r[i] - r_el[i]));
    for (int j = 0; j < n; j++) {
      etk = fmax(etk, fabs(rd->K[i * n + j] - K_el[i * n + j]));
    }
  }
  /* the volume a closed face set encloses (every boundary face of the block, oriented out of
   * it: minus its volume) at q, against the faces' own sum; on an open set the per-face shares
   * 1/3 int x.n da are not potentials of the face loads, only their sum over a closed surface */
  for (int f = 0; f < b.me->nface; f++) {
    fch[f] = 0;
  }
  CS_EXPECT(csf_romChamberTensors(r, 1, fch, &err) == CS_OK);
  double vf = 0, xf[18], fe[18];
  for (int f = 0; f < b.me->nface; f++) {
    double v;
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        const int g = 3 * b.me->face[6 * f + a] + i;
        xf[3 * a + i] = b.me->x[g] + b.d->u[g];
      }
    }
    csf_faceKernel(xf, 1.0, fe, NULL, &v);
    vf += v;
  }
  const double vt = csf_romChamberVolume(r, 0, q);
  printf("  chambers in closed form: |dr| %.2e, |dK| %.2e (relative); closed volume %.9f mm^3 "
         "against the faces' %.9f\n", etr / mr, etk / mk, vt, vf);
  /* exact up to round-off (the cubic's coefficients by exact differences of a linear H) */
  CS_EXPECT_NEAR(etr / mr, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(etk / mk, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(vt, vf, 1e-12 * fabs(vf), 0);
  free(fch);
  free(rp), free(K), free(KV), free(col), free(y), free(V), free(fp);
  csf_romDataDestroy(rd);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* ramp the rom from q = 0 to load factor 1 in nstep steps */
static csStatus romRampWith(const csfRom* r, csfRomData* rd, const csfModel* m, int nstep,
                            const csfRomNewtonOptions* op, csError* err) {
  const csfRomNewtonOptions o = *op;
  for (int s = 1; s <= nstep; s++) {
    const double lam = (double)s / nstep;
    double* fp = rtFacePressure(m, lam);
    csfRomLoad ld = {fp, {m->gravity[0], m->gravity[1], m->gravity[2]}, NULL};
    csStatus st = csf_romNewton(r, rd, &ld, &o, NULL, err);
    free(fp);
    if (st != CS_OK) {
      printf("  rom step %d: %s\n", s, err->msg);
      return st;
    }
  }
  return CS_OK;
}

static csStatus romRamp(const csfRom* r, csfRomData* rd, const csfModel* m, int nstep,
                        csError* err) {
  const csfRomNewtonOptions o = csf_romNewtonDefault();
  return romRampWith(r, rd, m, nstep, &o, err);
}

static double maxAbsDiff(int n, const double* a, const double* b, double* amax) {
  double e = 0;
  *amax = 0;
  for (int i = 0; i < n; i++) {
    e = fmax(e, fabs(a[i] - b[i]));
    *amax = fmax(*amax, fabs(b[i]));
  }
  return e;
}


/* the FE's solution of the clamped block under pressure and gravity (kappa of the FE's
 * default material), in 4 load steps; returns u at loads 0.5 and 1 */
static void feSolution(RtBox* b, double* u_half, double* u_one) {
  csError err = {0};
  csfNewtonOptions o = csf_newtonDefault();
  for (int s = 1; s <= 4; s++) {
    const csStatus st = csf_newtonSolve(b->m, b->d, P_BOX * s / 4.0, &o, NULL, &err);
    if (st != CS_OK) {
      printf("  FE step %d: %s\n", s, err.msg);
    }
    CS_EXPECT(st == CS_OK);
    if (s == 2) {
      memcpy(u_half, b->d->u, (size_t)b->m->ndof * sizeof(double));
    }
  }
  memcpy(u_one, b->d->u, (size_t)b->m->ndof * sizeof(double));
}


/* V = every free dof of the block (ndof x n, identity on the free dofs), and the FE's face
 * pressure per unit load (1 MPa) scaled to the rom's loads (P_BOX) */
static double* fullBasis(RtBox* b, int* n_out) {
  const csfModel* m = b->m;
  const int nd = m->ndof;
  int n = 0;
  for (int i = 0; i < nd; i++) {
    n += !m->fixed[i];
  }
  double* V = calloc((size_t)nd * n, sizeof(double));
  for (int i = 0, j = 0; i < nd; i++) {
    if (!m->fixed[i]) {
      V[(size_t)i * n + j++] = 1.0;
    }
  }
  for (int f = 0; f < m->mesh->nface; f++) {
    b->m->face_p[f] *= P_BOX;
  }
  *n_out = n;
  return V;
}


/* V = every free dof: the rom is the FE, and its Newton lands on the FE's equilibrium */
static void test_full_basis_reproduces_the_fe_equilibrium(void) {
  RtBox b;
  rtBoxCreate(&b, 4, 6.0, CSF_KAPPA_RATIO * 2 * 0.11, 0, 1);
  const csfModel* m = b.m;
  const int nd = m->ndof;
  double* uh = malloc(nd * sizeof(double));
  double* u1 = malloc(nd * sizeof(double));
  feSolution(&b, uh, u1);
  int n;
  double* V = fullBasis(&b, &n);
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csfRomData* rd = csf_romDataCreate(r, &err);
  CS_EXPECT(romRamp(r, rd, m, 4, &err) == CS_OK);
  double* u = malloc(nd * sizeof(double));
  csf_romExpand(r, rd->q, u);
  double umax, e = maxAbsDiff(nd, u, u1, &umax);
  printf("  full basis (n = %d): max |u_rom - u_fe| = %.2e mm of %.3f mm (%ld Newton "
         "iterations)\n", n, e, umax, rd->n_newton);
  /* both Newton solves stop at |R| <= 1e-8 (|f_int| + |f_ext|): a displacement difference of
   * order 1e-8 |u| times the conditioning; 1e-6 |u| */
  CS_EXPECT_NEAR(e / umax, 0.0, 1e-6, 0);
  free(V), free(u), free(uh), free(u1);
  csf_romDataDestroy(rd);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* The lagged tangent (csfRomNewtonOptions.k_lag): on the full basis (the rom is the FE) the
 * same four load steps reach the FE's equilibrium to the Newton tolerance as Newton does, with
 * fewer tangents formed (the factor is kept across steps and iterates while |r| contracts) */
static void test_lagged_tangent_reaches_the_equilibrium_with_fewer_tangents(void) {
  RtBox b;
  rtBoxCreate(&b, 4, 6.0, CSF_KAPPA_RATIO * 2 * 0.11, 0, 1);
  const csfModel* m = b.m;
  const int nd = m->ndof;
  double* uh = malloc(nd * sizeof(double));
  double* u1 = malloc(nd * sizeof(double));
  feSolution(&b, uh, u1);
  int n;
  double* V = fullBasis(&b, &n);
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  /* the pressure face in closed form, as the actuators' chambers (its Hessian's scratch must
   * not be the kept factor's) */
  int* fch = malloc((size_t)b.me->nface * sizeof(int));
  for (int f = 0; f < b.me->nface; f++) {
    fch[f] = b.me->face_tag[f] == 2 ? 0 : -1;
  }
  CS_EXPECT(csf_romChamberTensors(r, 1, fch, &err) == CS_OK);
  free(fch);
  double* u = malloc(nd * sizeof(double));
  long tangents[3], iters[3];
  static const char* const kName[3] = {"Newton", "lagged tangent (k_lag 0.25)",
                                       "lagged tangent with BFGS (k_lag 0.25, 8 pairs)"};
  for (int lag = 0; lag < 3; lag++) {
    csfRomData* rd = csf_romDataCreate(r, &err);
    csfRomNewtonOptions o = csf_romNewtonDefault();
    o.k_lag = lag ? 0.25 : 0.0;
    o.bfgs = lag == 2 ? 8 : 0;
    CS_EXPECT(romRampWith(r, rd, m, 4, &o, &err) == CS_OK);
    csf_romExpand(r, rd->q, u);
    double umax, e = maxAbsDiff(nd, u, u1, &umax);
    tangents[lag] = rd->n_tangent, iters[lag] = rd->n_newton;
    printf("  %s: max |u_rom - u_fe| = %.2e mm of %.3f mm; %ld iterations, %ld evaluations, "
           "%ld tangents\n", kName[lag], e, umax, rd->n_newton, rd->n_eval, rd->n_tangent);
    /* the residual test decides all three: as test_full_basis_reproduces_the_fe_equilibrium */
    CS_EXPECT_NEAR(e / umax, 0.0, 1e-6, 0);
    csf_romDataDestroy(rd);
  }
  CS_EXPECT(tangents[1] < tangents[0] && tangents[2] < tangents[0]);
  CS_EXPECT(iters[1] > tangents[1] && iters[2] > tangents[2]); /* steps on a kept factor */
  free(V), free(u), free(uh), free(u1);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* uniform in [0, 1) from a fixed LCG (Numerical Recipes' constants): reproducible draws */
static double urand(unsigned* state) {
  *state = *state * 1664525u + 1013904223u;
  return (double)(*state >> 8) / 16777216.0;
}

/* The BFGS update of the kept factor (csfRomNewtonOptions.bfgs), against its closed-form
 * properties: without pairs H is the factor's inverse (K H x = x); with pairs stored, H meets
 * the secant equation of the last one, H y = s (Nocedal and Wright 2006, eq. 6.6), and stays
 * symmetric (x1 . H x2 = x2 . H x1); a pair against the curvature condition (y . s <= 0) is
 * refused; past the memory the oldest pair leaves and the secant equation of the newest holds. */
static void test_bfgs_update_meets_the_secant_equation(void) {
  RtBox b;
  rtBoxCreate(&b, 4, 6.0, CSF_KAPPA_RATIO * 2 * 0.11, 0, 1);
  const csfModel* m = b.m;
  int n;
  double* V = fullBasis(&b, &n);
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csfRomData* rd = csf_romDataCreate(r, &err);
  CS_EXPECT(romRamp(r, rd, m, 2, &err) == CS_OK); /* a loaded state: K is not the rest one */
  csfRomLoad none = {0};
  rd->sync = 1;
  CS_EXPECT(csf_romEvaluate(r, rd, &none, 1) == 0);
  CS_EXPECT(csf_romFactorTangent(r, rd, &err) == CS_OK);
  const size_t nn = (size_t)n;
  double* x = malloc(nn * sizeof(double));
  double* hx = malloc(nn * sizeof(double));
  double* s = malloc(nn * sizeof(double));
  double* y = malloc(nn * sizeof(double));
  unsigned seed = 7u;
  double kmax = 0;
  for (size_t i = 0; i < nn * nn; i++) {
    kmax = fmax(kmax, fabs(rd->K[i]));
  }
  /* no pairs: K (H x) = x */
  for (size_t j = 0; j < nn; j++) {
    x[j] = urand(&seed) - 0.5;
  }
  memcpy(hx, x, nn * sizeof(double));
  csf_romQuasiNewtonApply(r, rd, hx);
  double e0 = 0;
  for (size_t i = 0; i < nn; i++) {
    double kh = 0;
    for (size_t j = 0; j < nn; j++) {
      kh += rd->K[i * nn + j] * hx[j];
    }
    e0 = fmax(e0, fabs(kh - x[i]));
  }
  /* pairs: s random, y = K s scaled per pair plus a perturbation (a secant of another curvature)
   * so that H differs from K^-1 */
  double esec = 0, esym = 0;
  int refused = 0, stored = 0;
  for (int k = 0; k < 12; k++) {
    for (size_t j = 0; j < nn; j++) {
      s[j] = urand(&seed) - 0.5;
    }
    for (size_t i = 0; i < nn; i++) {
      double ks = 0;
      for (size_t j = 0; j < nn; j++) {
        ks += rd->K[i * nn + j] * s[j];
      }
      y[i] = (1.0 + 0.3 * k) * ks + 0.05 * kmax * (urand(&seed) - 0.5);
    }
    stored += csf_romQuasiNewtonPush(r, rd, s, y, 5);
    memcpy(hx, y, nn * sizeof(double));
    csf_romQuasiNewtonApply(r, rd, hx);
    double ds = 0, sn = 0;
    for (size_t j = 0; j < nn; j++) {
      ds = fmax(ds, fabs(hx[j] - s[j])), sn = fmax(sn, fabs(s[j]));
    }
    esec = fmax(esec, ds / sn);
    /* a pair with y . s < 0 is refused */
    for (size_t j = 0; j < nn; j++) {
      y[j] = -y[j];
    }
    refused += csf_romQuasiNewtonPush(r, rd, s, y, 5) == 0;
  }
  /* symmetry of H with 5 pairs */
  for (size_t j = 0; j < nn; j++) {
    x[j] = urand(&seed) - 0.5, s[j] = urand(&seed) - 0.5;
  }
  memcpy(hx, x, nn * sizeof(double));
  csf_romQuasiNewtonApply(r, rd, hx);
  memcpy(y, s, nn * sizeof(double));
  csf_romQuasiNewtonApply(r, rd, y);
  double a1 = 0, a2 = 0;
  for (size_t j = 0; j < nn; j++) {
    a1 += s[j] * hx[j], a2 += x[j] * y[j];
  }
  esym = fabs(a1 - a2) / fmax(fabs(a1), 1e-300);
  printf("  n = %d: K H x - x %.1e (|x| <= 0.5); secant H y = s %.1e relative over 12 pairs "
         "(memory 5, %d stored, %d kept); %d of 12 pairs with y.s < 0 refused; asymmetry %.1e\n",
         n, e0, esec, stored, rd->bf_k, refused, esym);
  /* round-off of an LU solve and a few rank-two corrections on a K of condition ~1e4-1e6 */
  CS_EXPECT_NEAR(e0, 0.0, 1e-8, 0);
  CS_EXPECT_NEAR(esec, 0.0, 1e-8, 0);
  CS_EXPECT_NEAR(esym, 0.0, 1e-8, 0);
  CS_EXPECT(stored == 12 && refused == 12 && rd->bf_k == 5);
  free(x), free(hx), free(s), free(y), free(V);
  csf_romDataDestroy(rd);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* V = two FE snapshots (orthonormalised): the reduced Newton returns both to the Newton
 * tolerance (each lies in the span and makes V^T R vanish) */
static void test_snapshot_basis_reproduces_its_snapshots(void) {
  RtBox b;
  rtBoxCreate(&b, 4, 6.0, CSF_KAPPA_RATIO * 2 * 0.11, 0, 1);
  const csfModel* m = b.m;
  const int nd = m->ndof, n = 2;
  double* uh = malloc(nd * sizeof(double));
  double* u1 = malloc(nd * sizeof(double));
  feSolution(&b, uh, u1);
  double* V = calloc((size_t)nd * n, sizeof(double));
  /* Gram-Schmidt in the Euclidean product (any basis of the span will do) */
  double a = 0, c = 0, s2 = 0;
  for (int i = 0; i < nd; i++) {
    a += uh[i] * uh[i];
  }
  for (int i = 0; i < nd; i++) {
    V[(size_t)i * n] = uh[i] / sqrt(a);
    c += V[(size_t)i * n] * u1[i];
  }
  for (int i = 0; i < nd; i++) {
    V[(size_t)i * n + 1] = u1[i] - c * V[(size_t)i * n];
    s2 += V[(size_t)i * n + 1] * V[(size_t)i * n + 1];
  }
  for (int i = 0; i < nd; i++) {
    V[(size_t)i * n + 1] /= sqrt(s2);
  }
  for (int f = 0; f < m->mesh->nface; f++) {
    b.m->face_p[f] *= P_BOX;
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csfRomData* rd = csf_romDataCreate(r, &err);
  double* u = malloc(nd * sizeof(double));
  /* the FE's load steps 0.25 ... 1 (from rest straight to 0.5 the reduced Newton diverges:
   * its first iterate leaves the two-snapshot span's valley of small volume change, where the
   * bulk modulus makes |r| grow 3000-fold) */
  double umax, e1 = 0, eh = 0;
  csfRomNewtonOptions o = csf_romNewtonDefault();
  for (int s = 1; s <= 4; s++) {
    double* fp = rtFacePressure(m, s / 4.0);
    csfRomLoad ld = {fp, {m->gravity[0], m->gravity[1], m->gravity[2]}, NULL};
    CS_EXPECT(csf_romNewton(r, rd, &ld, &o, NULL, &err) == CS_OK);
    free(fp);
    csf_romExpand(r, rd->q, u);
    if (s == 2) {
      eh = maxAbsDiff(nd, u, uh, &umax) / umax;
    }
  }
  e1 = maxAbsDiff(nd, u, u1, &umax);
  printf("  two-snapshot basis: max |u_rom - u_fe| / max |u_fe| at load 0.5: %.2e, at load 1: "
         "%.2e (of %.3f mm)\n", eh, e1 / umax, umax);
  CS_EXPECT_NEAR(eh, 0.0, 1e-6, 0);
  CS_EXPECT_NEAR(e1 / umax, 0.0, 1e-6, 0);
  memset(rd->q, 0, n * sizeof(double));
  CS_EXPECT(romRamp(r, rd, m, 1, &err) == CS_OK); /* load 1 in one step from rest */
  csf_romExpand(r, rd->q, u);
  double e2 = maxAbsDiff(nd, u, u1, &umax);
  printf("  the same in one load step from rest: %.2e mm\n", e2);
  CS_EXPECT_NEAR(e2 / umax, 0.0, 1e-6, 0);
  free(V), free(u), free(uh), free(u1);
  csf_romDataDestroy(rd);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* every element at weight 1 through csf_romSetWeights, in reversed order: the unreduced model
 * to round-off; weights 2 on the bodies and fibres double their part */
static void test_unit_weights_on_every_element_equal_the_unreduced_model(void) {
  RtBox b;
  rtBoxCreate(&b, 2, 3.0, CSF_KAPPA_RATIO * 2 * 0.11, 1, 1);
  const csfModel* m = b.m;
  const int nd = m->ndof, n = 4;
  double* V = calloc((size_t)nd * n, sizeof(double));
  srand(5);
  for (int i = 0; i < nd; i++) {
    for (int j = 0; !m->fixed[i] && j < n; j++) {
      V[(size_t)i * n + j] = 0.02 * ((double)rand() / RAND_MAX - 0.5) * b.me->x[3 * (i / 3) + 2];
    }
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csfRomData* d0 = csf_romDataCreate(r, &err);
  d0->sync = 1;
  const double q[4] = {0.5, -0.3, 0.8, 0.2};
  memcpy(d0->q, q, sizeof q);
  double* fp = rtFacePressure(m, 0.03);
  csfRomLoad ld = {fp, {0, -9810.0, 0}, NULL};
  CS_EXPECT(csf_romEvaluate(r, d0, &ld, 1) == 0);
  double r0[4], K0[16];
  memcpy(r0, d0->r, sizeof r0);
  memcpy(K0, d0->K, sizeof K0);
  const int cnt[CSF_ROM_NSET] = {m->mesh->ntet, m->nfib, m->mesh->nface};
  for (int s = 0; s < CSF_ROM_NSET; s++) {
    int* idx = malloc(cnt[s] * sizeof(int));
    double* w = malloc(cnt[s] * sizeof(double));
    for (int e = 0; e < cnt[s]; e++) {
      idx[e] = cnt[s] - 1 - e, w[e] = 1.0;
    }
    CS_EXPECT(csf_romSetWeights(r, (csfRomSet)s, cnt[s], idx, w, &err) == CS_OK);
    free(idx), free(w);
  }
  CS_EXPECT(csf_romEvaluate(r, d0, &ld, 1) == 0);
  double er = 0, ek = 0, mr = 0, mk = 0;
  for (int j = 0; j < n; j++) {
    er = fmax(er, fabs(d0->r[j] - r0[j]));
    mr = fmax(mr, fabs(r0[j]));
    for (int k = 0; k < n; k++) {
      ek = fmax(ek, fabs(d0->K[j * n + k] - K0[j * n + k]));
      mk = fmax(mk, fabs(K0[j * n + k]));
    }
  }
  printf("  every element at weight 1, reversed: |dr| %.2e of %.2e, |dK| %.2e of %.2e\n", er, mr,
         ek, mk);
  CS_EXPECT_NEAR(er / mr, 0.0, 1e-13, 0);
  CS_EXPECT_NEAR(ek / mk, 0.0, 1e-13, 0);
  /* the element forces sum to the residual less gravity: r = sum_sets sum_e G_e - G g */
  double sum[4] = {0, 0, 0, 0};
  for (int s = 0; s < CSF_ROM_NSET; s++) {
    double* G = malloc((size_t)cnt[s] * n * sizeof(double));
    CS_EXPECT(csf_romElementForces(r, d0, &ld, (csfRomSet)s, G) == 0);
    for (int e = 0; e < cnt[s]; e++) {
      for (int j = 0; j < n; j++) {
        sum[j] += G[(size_t)e * n + j];
      }
    }
    free(G);
  }
  double eg = 0;
  for (int j = 0; j < n; j++) {
    sum[j] -= r->G[3 * j + 1] * ld.gravity[1];
    eg = fmax(eg, fabs(sum[j] - r0[j]));
  }
  printf("  element forces summed: |sum - r| %.2e of %.2e\n", eg, mr);
  CS_EXPECT_NEAR(eg / mr, 0.0, 1e-13, 0);
  /* a negative weight is refused */
  int one = 0;
  double neg = -1.0;
  CS_EXPECT(csf_romSetWeights(r, CSF_ROM_SET_TET, 1, &one, &neg, &err) == CS_ERR_ARG);
  free(V), free(fp);
  csf_romDataDestroy(d0);
  csf_romDestroy(r);
  rtBoxDestroy(&b);
}


/* A model finalised for the kernels only (csf_modelFinalizeKernels: a leg file's, no sparse
 * pattern; session romsweep) gives the reduced residual and tangent of the fully finalised one
 * bit for bit, and the FE's solvers refuse it. */
static void test_kernels_only_model_gives_the_same_rom_and_no_fe_solver(void) {
  RtBox b;
  rtBoxCreate(&b, 2, 3.0, CSF_KAPPA_RATIO * 2 * 0.11, 1, 1);
  csError err = {0};
  /* the same block, model and fibre, finalised for the kernels only */
  csfMaterial mat = b.m->mat;
  csfModel* mk = csf_modelCreate(b.me, &mat, &err);
  if (!mk) {
    CS_EXPECT(mk != NULL);
    rtBoxDestroy(&b);
    return;
  }
  CS_EXPECT(csf_modelAddPressure(mk, 2, 1.0) > 0);
  double fib[3 * 3] = {0.3, 0.2, 0.3, 1.7, 1.2, 1.5, 0.5, 0.7, 2.7}; /* rtBoxCreate's, L = 3 */
  CS_EXPECT(csf_modelAddFibre(mk, 3, fib, 31067.0, 0.0889, &err) == CS_OK);
  memcpy(mk->fixed, b.m->fixed, (size_t)mk->ndof);
  mk->fib_tension_only = 1;
  CS_EXPECT(csf_modelFinalizeKernels(mk, &err) == CS_OK);
  CS_EXPECT(mk->finalized == CSF_MODEL_KERNELS && mk->row_ptr == NULL && mk->nfib == b.m->nfib);
  const int nd = b.m->ndof, n = 4;
  double* V = calloc((size_t)nd * n, sizeof(double));
  srand(7);
  for (int i = 0; i < nd; i++) {
    for (int j = 0; !b.m->fixed[i] && j < n; j++) {
      V[(size_t)i * n + j] = 0.02 * ((double)rand() / RAND_MAX - 0.5) * b.me->x[3 * (i / 3) + 2];
    }
  }
  csfRom* r0 = csf_romCreate(b.m, n, V, &err);
  csfRom* r1 = csf_romCreate(mk, n, V, &err);
  CS_EXPECT(r0 && r1);
  csfRomData* d0 = csf_romDataCreate(r0, &err);
  csfRomData* d1 = csf_romDataCreate(r1, &err);
  const double q[4] = {0.5, -0.3, 0.8, 0.2};
  memcpy(d0->q, q, sizeof q);
  memcpy(d1->q, q, sizeof q);
  double* fp = rtFacePressure(b.m, 0.03);
  csfRomLoad ld = {fp, {0, -9810.0, 0}, NULL};
  CS_EXPECT(csf_romEvaluate(r0, d0, &ld, 1) == 0);
  CS_EXPECT(csf_romEvaluate(r1, d1, &ld, 1) == 0);
  const int same = !memcmp(d0->r, d1->r, n * sizeof(double)) &&
                   !memcmp(d0->K, d1->K, (size_t)n * n * sizeof(double));
  printf("  kernels-only model: |r| %.3g N, r and K %s; csf_dataCreate: ", d0->rnorm,
         same ? "bit for bit" : "DIFFER");
  CS_EXPECT(d0->rnorm > 0 && same);
  csfData* fd = csf_dataCreate(mk, &err);
  printf("%s\n", fd ? "accepted" : err.msg);
  CS_EXPECT(fd == NULL && strstr(err.msg, "csf_modelFinalize must run") != NULL);
  csf_dataDestroy(fd);
  free(V), free(fp);
  csf_romDataDestroy(d0), csf_romDataDestroy(d1);
  csf_romDestroy(r0), csf_romDestroy(r1);
  csf_modelDestroy(mk);
  rtBoxDestroy(&b);
}


int main(void) {
  CS_RUN(test_reduced_residual_and_tangent_match_the_fe_and_finite_differences);
  CS_RUN(test_full_basis_reproduces_the_fe_equilibrium);
  CS_RUN(test_lagged_tangent_reaches_the_equilibrium_with_fewer_tangents);
  CS_RUN(test_bfgs_update_meets_the_secant_equation);
  CS_RUN(test_snapshot_basis_reproduces_its_snapshots);
  CS_RUN(test_unit_weights_on_every_element_equal_the_unreduced_model);
  CS_RUN(test_kernels_only_model_gives_the_same_rom_and_no_fe_solver);
  return cs_testSummary();
}
