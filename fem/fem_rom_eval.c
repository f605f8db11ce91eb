/* fem_rom_eval.c: the evaluation of the reduced-order FE model (fem_rom.h): the reduced
 * residual and tangent from fem's kernels (csf_romEvaluate) and every element's reduced force
 * (csf_romElementForces, ECSW's training matrix). The model and its data are fem_rom.c, the
 * Newton on q fem_rom_newton.c.
 *
 * Rationale.
 * Every element term is gathered through its own rows of the basis: u_e = V_e q (30 rows for a
 * Tet10 or a fibre inside one host, 60 for a fibre tied to two, 18 for a pressure face), the
 * kernel gives f_e and k_e, and r += w_e V_e^T f_e, K += w_e V_e^T k_e V_e. The cost per element
 * is O(m n + m^2 n + m n^2) for m element dofs and n reduced coordinates, independent of the
 * FE's size: a hyper-reduced model evaluates a few hundred elements instead of tens of
 * thousands. Gravity and dead loads are projected once, exactly, over every element (G,
 * fem_rom.c) and never hyper-reduced: here they are only added.
 * The kernels' state variables: the mixed Tet10 takes the element dilatation state theta_e in
 * its geometric stiffness; here theta_e = v/V of the current q (one residual-only kernel call
 * gives v/V, a second one the tangent), the converged value of the FE's three-field Newton, so
 * the reduced tangent is the exact derivative of the reduced residual (tested against finite
 * differences). The fibres likewise take S_state = S(E(q)). */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"

/* element displacement ue (3 nn) = V_e q over the element's nodes */
void csf_romGather(const csfRom* r, const double* q, int nn, const int* nodes, double* ue) {
  const int n = r->n;
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      const double* row = r->V + (size_t)(3 * nodes[a] + i) * (size_t)n;
      double s = 0;
      for (int j = 0; j < n; j++) {
        s += row[j] * q[j];
      }
      ue[3 * a + i] = s;
    }
  }
}

/* fibre f's current host-node positions x (3 nn) at q and its chord coefficients (a fibre
 * inside one host: its two coefficient halves summed into c10, fem_assembly.c); returns nn */
static int fibreGeometry(const csfRom* r, const double* q, int f, double x[60], double c10[10],
                         const double** cf) {
  const csfModel* m = r->fem;
  const int* fv = m->fib_node + 20 * (size_t)f;
  const int nn = m->fib_single[f] ? 10 : 20;
  *cf = m->fib_coef + 20 * (size_t)f;
  csf_romGather(r, q, nn, fv, x);
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      x[3 * a + i] += m->mesh->x[3 * fv[a] + i];
    }
  }
  if (nn == 10) {
    for (int a = 0; a < 10; a++) {
      c10[a] = (*cf)[a] + (*cf)[10 + a];
    }
    *cf = c10;
  }
  return nn;
}

/* rr += w V_e^T fe; K += w V_e^T ke V_e (ke: 3nn x 3nn row-major, may be NULL) */
static void scatter(const csfRom* r, csfRomData* d, int nn, const int* nodes, double w,
                    const double* fe, const double* ke, double* rr) {
  const int n = r->n, m = 3 * nn;
  for (int k = 0; k < m; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double f = w * fe[k];
    for (int j = 0; j < n; j++) {
      rr[j] += row[j] * f;
    }
  }
  if (!ke) {
    return;
  }
  /* T = ke V_e (m x n), then K += w V_e^T T */
  double* T = d->ke_v;
  memset(T, 0, (size_t)m * (size_t)n * sizeof(double));
  for (int k = 0; k < m; k++) {
    double* Tk = T + (size_t)k * (size_t)n;
    for (int l = 0; l < m; l++) {
      const double kv = ke[(size_t)k * (size_t)m + (size_t)l];
      if (kv == 0.0) {
        continue;
      }
      const double* row = r->V + (size_t)(3 * nodes[l / 3] + l % 3) * (size_t)n;
      for (int j = 0; j < n; j++) {
        Tk[j] += kv * row[j];
      }
    }
  }
  for (int k = 0; k < m; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double* Tk = T + (size_t)k * (size_t)n;
    for (int i = 0; i < n; i++) {
      const double vi = w * row[i];
      if (vi == 0.0) {
        continue;
      }
      double* Ki = d->K + (size_t)i * (size_t)n;
      for (int j = 0; j < n; j++) {
        Ki[j] += vi * Tk[j];
      }
    }
  }
}

/* A Tet10's share, its tangent symmetric (the mixed kernel's is: fem_element.h): rr += w V_e^T fe
 * as scatter(), and the upper triangle of w V_e^T ke V_e into d->Ku (csf_romEvaluate mirrors it):
 * T = ke V_e (30 x n) row by row, then each row i of the triangle summed over the 30 element
 * dofs in a row buffer (L1-resident) and added to Ku once: half scatter()'s O(30 n^2) and no
 * pass over Ku per element dof. */
static void scatterTetSym(const csfRom* r, csfRomData* d, const int* nodes, double w,
                          const double* fe, const double* ke, double* rr) {
  const int n = r->n;
  const double* row[30];
  for (int k = 0; k < 30; k++) {
    row[k] = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double f = w * fe[k];
    for (int j = 0; j < n; j++) {
      rr[j] += row[k][j] * f;
    }
  }
  if (!ke) {
    return;
  }
  double* T = d->ke_v;
  for (int k = 0; k < 30; k++) {
    double* Tk = T + (size_t)k * (size_t)n;
    memset(Tk, 0, (size_t)n * sizeof(double));
    for (int l = 0; l < 30; l++) {
      const double kv = w * ke[30 * k + l];
      if (kv == 0.0) {
        continue;
      }
      for (int j = 0; j < n; j++) {
        Tk[j] += kv * row[l][j];
      }
    }
  }
  double* acc = d->ke_v + 60 * (size_t)n; /* (n) row buffer */
  for (int i = 0; i < n; i++) {
    memset(acc + i, 0, (size_t)(n - i) * sizeof(double));
    for (int k = 0; k < 30; k++) {
      const double vi = row[k][i];
      if (vi == 0.0) {
        continue;
      }
      const double* Tk = T + (size_t)k * (size_t)n;
      for (int j = i; j < n; j++) {
        acc[j] += vi * Tk[j];
      }
    }
    double* Ki = d->Ku + (size_t)i * (size_t)n;
    for (int j = i; j < n; j++) {
      Ki[j] += acc[j];
    }
  }
}

/* v = V_e^T g (n) over a Tet10's rows: the element's volume gradient in reduced coordinates */
static void reduceVector(const csfRom* r, const int* nodes, const double* g, double* v) {
  const int n = r->n;
  memset(v, 0, (size_t)n * sizeof(double));
  for (int k = 0; k < 30; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    for (int j = 0; j < n; j++) {
      v[j] += row[j] * g[k];
    }
  }
}

/* The Tet10s of the mixed model (fem_rom.h csfRom.m) into rint and d->K: pass 1 the element
 * volumes and b = sum_e w_e P_e (v_e - V_e), p^ = A^-1 b; pass 2 each element's force with its
 * pressure p_e = P_e . p^ in place of the kernel's own kappa (v_e / V_e - 1) and, for the
 * tangent, the kernel's matrix at theta_e = 1 + p_e,state / kappa (the geometric term of the
 * state pressure, as the FE's three-field Newton; sync: p_e) less its element bulk term
 * kappa / V_e g g^T, which the reduced one B^T A^-1 B replaces. Returns 1 on an inverted
 * element. */
static int mixedTets(const csfRom* r, csfRomData* d, int want_k, double* rint) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n, mm = r->m;
  const double kappa = m->mat.kappa;
  double* b = d->ph;
  memset(b, 0, (size_t)mm * sizeof(double));
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    double ue[30], gv[30], vr, jm;
    csf_romGather(r, d->q, 10, me->tet + 10 * e, ue);
    if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                      1.0, d->rel + 30 * (size_t)e, NULL, &vr, gv, &jm)) {
      return 1;
    }
    d->vr[e] = vr;
    memcpy(d->gel + 30 * (size_t)e, gv, sizeof gv);
    const double c = r->w[CSF_ROM_SET_TET][k] * (vr - 1.0) * m->vol[e];
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    for (int i = 0; i < mm; i++) {
      b[i] += c * Pe[i];
    }
  }
  csf_romMixedSolve(r, b); /* now p^ */
  if (want_k) {
    memset(d->Bm, 0, (size_t)mm * (size_t)n * sizeof(double));
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    const int* tv = me->tet + 10 * e;
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    const double* gv = d->gel + 30 * (size_t)e;
    const double w = r->w[CSF_ROM_SET_TET][k];
    double pe = 0;
    for (int i = 0; i < mm; i++) {
      pe += Pe[i] * b[i];
    }
    double fe[30], ke[900];
    const double dp = pe - kappa * (d->vr[e] - 1.0);
    const double* re = d->rel + 30 * (size_t)e;
    for (int a = 0; a < 30; a++) {
      fe[a] = re[a] + dp * gv[a];
    }
    if (want_k) {
      double ue[30], rtmp[30], gtmp[30], vr, jm;
      csf_romGather(r, d->q, 10, tv, ue);
      const double th = d->sync ? 1.0 + pe / kappa : d->theta[e];
      if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e],
                        ue, th, rtmp, ke, &vr, gtmp, &jm)) {
        return 1;
      }
      const double s = kappa / m->vol[e];
      for (int a = 0; a < 30; a++) {
        for (int c = 0; c < 30; c++) {
          ke[30 * a + c] -= s * gv[a] * gv[c];
        }
      }
      double* vg = d->mtmp + mm; /* (n) V_e^T g_e */
      reduceVector(r, tv, gv, vg);
      for (int i = 0; i < mm; i++) {
        const double c = w * Pe[i];
        if (c == 0.0) {
          continue;
        }
        double* Bi = d->Bm + (size_t)i * (size_t)n;
        for (int j = 0; j < n; j++) {
          Bi[j] += c * vg[j];
        }
      }
    }
    scatterTetSym(r, d, tv, w, fe, want_k ? ke : NULL, rint);
  }
  if (want_k) {
    /* K += B^T A^-1 B, column by column of B */
    double* col = d->mtmp;
    double* ab = d->Bm + (size_t)mm * n; /* (m x n) A^-1 B */
    for (int j = 0; j < n; j++) {
      for (int i = 0; i < mm; i++) {
        col[i] = d->Bm[(size_t)i * n + j];
      }
      csf_romMixedSolve(r, col);
      for (int i = 0; i < mm; i++) {
        ab[(size_t)i * n + j] = col[i];
      }
    }
    for (int i = 0; i < mm; i++) {
      const double* Bi = d->Bm + (size_t)i * n;
      const double* ABi = ab + (size_t)i * n;
      for (int a = 0; a < n; a++) {
        double* Ka = d->K + (size_t)a * n;
        for (int c = 0; c < n; c++) {
          Ka[c] += Bi[a] * ABi[c];
        }
      }
    }
  }
  return 0;
}

int csf_romEvaluate(const csfRom* r, csfRomData* d, const csfRomLoad* load, int want_k) {
  if (!r || !d || !load || d->n != r->n || d->m != r->m || d->mf != r->mf) {
    return -1;
  }
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n;
  double* rint = d->tmp; /* internal part, then the external one into d->r */
  memset(rint, 0, (size_t)n * sizeof(double));
  memset(d->r, 0, (size_t)n * sizeof(double));
  if (want_k) {
    memset(d->K, 0, (size_t)n * (size_t)n * sizeof(double));
    memset(d->Ku, 0, (size_t)n * (size_t)n * sizeof(double));
  }
  /* Tet10 bodies */
  if (r->m > 0) {
    if (mixedTets(r, d, want_k, rint)) {
      return 1;
    }
  }
  for (int k = 0; r->m == 0 && k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    const int* tv = me->tet + 10 * e;
    double ue[30], re[30], ke[900], gv[30], vr, jm;
    csf_romGather(r, d->q, 10, tv, ue);
    const double* dN = m->dNdX + 120 * (size_t)e;
    const double* wq = m->wq + 4 * (size_t)e;
    /* the residual does not depend on theta_e; the tangent takes the state, or v/V (sync:
     * a residual call first gives it) */
    double th = d->theta[e];
    if (want_k && d->sync) {
      if (csf_tetKernel(&m->mat, dN, wq, m->vol[e], ue, 1.0, re, NULL, &vr, gv, &jm)) {
        return 1;
      }
      th = vr;
    }
    if (csf_tetKernel(&m->mat, dN, wq, m->vol[e], ue, th, re, want_k ? ke : NULL, &vr, gv, &jm)) {
      return 1;
    }
    d->vr[e] = vr;
    memcpy(d->gel + 30 * (size_t)e, gv, sizeof gv);
    scatterTetSym(r, d, tv, r->w[CSF_ROM_SET_TET][k], re, want_k ? ke : NULL, rint);
  }
  /* fibres through their chord operators (csfRom.fib_D): the kernel on the chord alone (one
   * "node" of coefficient 1: its force f_d = dW/dd and 3 x 3 tangent H), then
   * r += w D^T f_d, K += w D^T H D; the mixed fibre field (csfRom.mf) in fem_rom_fibre.c */
  if (r->mf > 0) {
    csf_romFibresMixed(r, d, want_k, rint);
  }
  for (int k = 0; r->mf == 0 && k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
    const double one = 1.0;
    double dch[3], fd[3], H[9], E = 0, dout[3], S, dS;
    for (int i = 0; i < 3; i++) {
      const double* Di = D + (size_t)i * (size_t)n;
      double s = r->fib_X[3 * k + i];
      for (int j = 0; j < n; j++) {
        s += Di[j] * d->q[j];
      }
      dch[i] = s;
    }
    S = d->fib_S[f];
    if (want_k && d->sync) {
      csf_fibreKernel(1, &one, dch, m->fib_L0[f], m->fib_EA[f], S, m->fib_tension_only,
                      m->fib_geo_tension, fd, NULL, &E, dout);
      csf_fibreLaw(m->fib_tension_only, E, &S, &dS);
    }
    const int loaded = csf_fibreKernel(1, &one, dch, m->fib_L0[f], m->fib_EA[f], S,
                                       m->fib_tension_only, m->fib_geo_tension, fd,
                                       want_k ? H : NULL, &E, dout);
    d->fib_E[f] = E;
    memcpy(d->fib_d + 3 * (size_t)f, dout, sizeof dout);
    if (!loaded) {
      continue;
    }
    const double w = r->w[CSF_ROM_SET_FIBRE][k];
    for (int j = 0; j < n; j++) {
      rint[j] += w * (D[j] * fd[0] + D[n + j] * fd[1] + D[2 * (size_t)n + j] * fd[2]);
    }
    if (!want_k) {
      continue;
    }
    /* T = w H D (3 x n), K += D^T T */
    double* T = d->ke_v;
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < n; j++) {
        T[(size_t)i * n + j] = w * (H[3 * i] * D[j] + H[3 * i + 1] * D[n + j] +
                                    H[3 * i + 2] * D[2 * (size_t)n + j]);
      }
    }
    for (int a = 0; a < n; a++) { /* the upper triangle (symmetric: H is) */
      const double d0 = D[a], d1 = D[n + a], d2 = D[2 * (size_t)n + a];
      double* Ka = d->Ku + (size_t)a * n;
      for (int j = a; j < n; j++) {
        Ka[j] += d0 * T[j] + d1 * T[n + j] + d2 * T[2 * (size_t)n + j];
      }
    }
  }
  /* the bodies' and fibres' symmetric tangent from its upper triangle */
  for (int i = 0; want_k && i < n; i++) {
    const double* Ui = d->Ku + (size_t)i * (size_t)n;
    double* Ki = d->K + (size_t)i * (size_t)n;
    Ki[i] += Ui[i];
    for (int j = i + 1; j < n; j++) {
      Ki[j] += Ui[j];
      d->K[(size_t)j * n + i] += Ui[j];
    }
  }
  /* follower pressure: R -= f_ext, K += kfe (= -d f_ext / dx) */
  if (load->face_p) {
    for (int k = 0; k < r->nel[CSF_ROM_SET_FACE]; k++) {
      const int f = r->el[CSF_ROM_SET_FACE][k];
      const double p = load->face_p[f];
      if (p == 0.0 || (r->nch > 0 && r->face_ch[f] >= 0)) {
        continue; /* vented, or a chamber in closed form (below) */
      }
      const int* fn = me->face + 6 * (size_t)f;
      double xf[18], fe[18], kfe[324], vf;
      csf_romGather(r, d->q, 6, fn, xf);
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          xf[3 * a + i] += me->x[3 * fn[a] + i];
        }
      }
      csf_faceKernel(xf, p, fe, want_k ? kfe : NULL, &vf);
      for (int a = 0; a < 18; a++) {
        fe[a] = -fe[a];
      }
      scatter(r, d, 6, fn, r->w[CSF_ROM_SET_FACE][k], fe, want_k ? kfe : NULL, d->r);
    }
  }
  /* chambers in closed form: r -= p g_c(q), K -= p H_c(q) (the Ku scratch holds H(q); lu
   * holds the Newton's kept factor) */
  for (int c = 0; load->face_p && c < r->nch; c++) {
    double p = 0.0;
    for (int f = 0; f < me->nface; f++) {
      if (r->face_ch[f] == c) {
        p = load->face_p[f];
        break;
      }
    }
    if (p == 0.0) {
      continue;
    }
    double* Hq = d->Ku;
    csf_romChamberHessian(r, c, d->q, Hq);
    const double* H0 = r->ch_H + (size_t)c * (size_t)(n + 1) * (size_t)n * (size_t)n;
    const double* g0 = r->ch_g0 + (size_t)c * (size_t)n;
    for (int i = 0; i < n; i++) {
      double s = 0;
      for (int j = 0; j < n; j++) {
        s += (H0[(size_t)i * n + j] + Hq[(size_t)i * n + j]) * d->q[j];
      }
      d->r[i] -= p * (g0[i] + 0.5 * s);
    }
    if (want_k) {
      for (size_t i = 0; i < (size_t)n * (size_t)n; i++) {
        d->K[i] -= p * Hq[i];
      }
    }
  }
  /* gravity and dead loads, exact */
  for (int j = 0; j < n; j++) {
    d->r[j] -= r->G[3 * j] * load->gravity[0] + r->G[3 * j + 1] * load->gravity[1] +
               r->G[3 * j + 2] * load->gravity[2];
    if (load->f_dead) {
      d->r[j] -= load->f_dead[j];
    }
  }
  double ni = 0, ne = 0, nr = 0;
  for (int j = 0; j < n; j++) {
    ni += rint[j] * rint[j];
    ne += d->r[j] * d->r[j];
    d->r[j] += rint[j];
    nr += d->r[j] * d->r[j];
  }
  d->fnorm = sqrt(ni) + sqrt(ne);
  d->rnorm = sqrt(nr);
  d->n_eval++;
  d->n_tangent += want_k != 0;
  return isfinite(d->rnorm) ? 0 : 1;
}


int csf_romElementForcesWidth(const csfRom* r, csfRomSet set) {
  return r->n + (set == CSF_ROM_SET_TET ? r->m : 0) +
         (set == CSF_ROM_SET_FIBRE ? 4 * r->mf : 0);
}

/* The mixed model's Tet10 rows (csf_romElementForces): the unreduced model's p^ (every Tet10 at
 * weight 1: b over all of them, A over all of them), then per element the reduced force with
 * its pressure p_e = P_e . p^ and its constraint share P_e (v_e - V_e). */
static int mixedElementForces(const csfRom* r, csfRomData* d, double* G) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n, mm = r->m, wd = n + mm;
  const double kappa = m->mat.kappa;
  double* L = malloc((size_t)mm * (size_t)mm * sizeof(double));
  double* ph = calloc((size_t)mm, sizeof(double));
  csError err;
  if (!L || !ph || csf_romMixedFactorInto(r, 1, L, &err) != CS_OK) {
    free(L), free(ph);
    return -1;
  }
  memset(G, 0, (size_t)me->ntet * (size_t)wd * sizeof(double));
  for (int e = 0; e < me->ntet; e++) {
    double ue[30], vr, jm;
    csf_romGather(r, d->q, 10, me->tet + 10 * (size_t)e, ue);
    if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                      1.0, d->rel + 30 * (size_t)e, NULL, &vr, d->gel + 30 * (size_t)e, &jm)) {
      free(L), free(ph);
      return 1;
    }
    d->vr[e] = vr;
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    double* row = G + (size_t)e * wd + n;
    for (int i = 0; i < mm; i++) {
      row[i] = Pe[i] * (vr - 1.0) * m->vol[e];
      ph[i] += row[i];
    }
  }
  csf_romMixedSolveWith(mm, L, ph);
  for (int e = 0; e < me->ntet; e++) {
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    double pe = 0, fe[30];
    for (int i = 0; i < mm; i++) {
      pe += Pe[i] * ph[i];
    }
    const double dp = pe - kappa * (d->vr[e] - 1.0);
    const double* re = d->rel + 30 * (size_t)e;
    const double* gv = d->gel + 30 * (size_t)e;
    for (int a = 0; a < 30; a++) {
      fe[a] = re[a] + dp * gv[a];
    }
    scatter(r, d, 10, me->tet + 10 * (size_t)e, 1.0, fe, NULL, G + (size_t)e * wd);
  }
  free(L), free(ph);
  return 0;
}

int csf_romElementForces(const csfRom* r, csfRomData* d, const csfRomLoad* load, csfRomSet set,
                         double* G) {
  if (!r || !d || !load || !G || (int)set < 0 || set >= CSF_ROM_NSET || d->n != r->n ||
      d->m != r->m) {
    return -1;
  }
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const size_t n = (size_t)r->n;
  const int count[CSF_ROM_NSET] = {me->ntet, m->nfib, me->nface};
  if (set == CSF_ROM_SET_TET && r->m > 0) {
    return mixedElementForces(r, d, G);
  }
  if (set == CSF_ROM_SET_FIBRE && r->mf > 0) {
    return csf_romFibreElementForces(r, d->q, G);
  }
  memset(G, 0, (size_t)count[set] * n * sizeof(double));
  for (int e = 0; e < count[set]; e++) {
    double* row = G + (size_t)e * n;
    if (set == CSF_ROM_SET_TET) {
      double ue[30], re[30], gv[30], vr, jm;
      csf_romGather(r, d->q, 10, me->tet + 10 * (size_t)e, ue);
      if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                        1.0, re, NULL, &vr, gv, &jm)) {
        return 1;
      }
      scatter(r, d, 10, me->tet + 10 * (size_t)e, 1.0, re, NULL, row);
    } else if (set == CSF_ROM_SET_FIBRE) {
      const int* fv = m->fib_node + 20 * (size_t)e;
      const double* cf;
      double x[60], rf[60], c10[10], E, dch[3];
      const int nn = fibreGeometry(r, d->q, e, x, c10, &cf);
      if (csf_fibreKernel(nn, cf, x, m->fib_L0[e], m->fib_EA[e], 0.0, m->fib_tension_only,
                          m->fib_geo_tension, rf, NULL, &E, dch)) {
        scatter(r, d, nn, fv, 1.0, rf, NULL, row);
      }
    } else if (load->face_p && load->face_p[e] != 0.0) {
      const int* fn = me->face + 6 * (size_t)e;
      double xf[18], fe[18], vf;
      csf_romGather(r, d->q, 6, fn, xf);
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          xf[3 * a + i] += me->x[3 * fn[a] + i];
        }
      }
      csf_faceKernel(xf, load->face_p[e], fe, NULL, &vf);
      for (int a = 0; a < 18; a++) {
        fe[a] = -fe[a];
      }
      scatter(r, d, 6, fn, 1.0, fe, NULL, row);
    }
  }
  return 0;
}
