/* test_strain_vprod.c: the strain leg's velocity products Ġ_p u (robot_strain_lie.c,
 * csr_strainTwistRates_: the twist recursion's directional derivative along q, at fixed η and
 * base twist), which the step's assembly subtracts as M_p Ġ_p u (robot_strain_dyn.c).
 *
 * Cases:
 *  - velocity_products_match_differences: on a bent three-piece rod (flexible, rigid,
 *    flexible) and on the leg's five-piece layout, at strains scaled so that every Zanna
 *    step's |ω| is below the tangent's series threshold (0.05 rad), straddles it, or is above
 *    it (up to ~1 rad), the rates against Richardson-extrapolated central differences of
 *    csr_strainTwists_ (the computation the rates replace, there at one ε), both with each
 *    step's exponential formed by the rates and with the kinematics' (d->ks, as the step's
 *    assembly takes them); the twists that come with the former against csr_strainTwists_'s
 *    bit for bit; the kinematics' steps offered only at the q they were formed at, and not
 *    after the chain points' poses alone. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_strain_internal.h"
#include "strain_test_rods.h"

/* the differences' central quotient (V(q + ε η) - V(q - ε η)) / (2 ε) into D (np x 6) */
static void difference(const csrStrainModel* m, const double* q, const double* eta,
                       const double Vb[6], double eps, double* qs, double* Vp, double* Vm,
                       double* D) {
  const int n = csr_strainDofs(m);
  for (int j = 0; j < n; j++) {
    qs[j] = q[j] + eps * eta[j];
  }
  csr_strainTwists_(m, qs, eta, Vb, Vp);
  for (int j = 0; j < n; j++) {
    qs[j] = q[j] - eps * eta[j];
  }
  csr_strainTwists_(m, qs, eta, Vb, Vm);
  for (int i = 0; i < 6 * m->np; i++) {
    D[i] = (Vp[i] - Vm[i]) / (2 * eps);
  }
}


/* one rod at strains scaled by `scale`: the rates' largest difference from the extrapolated
 * differences relative to the largest rate (*e; *e_ks on the kinematics' steps), the
 * production difference's (*e_old), the largest Zanna |ω| (*thmax), whether the twists were
 * csr_strainTwists_'s bits (*same) and the kinematics' steps offered at their own q alone
 * (*guard) */
static void ratesCase(const csrStrainModel* m, double scale, double* e, double* e_ks,
                      double* e_old, double* thmax, int* same, int* guard) {
  const int n = csr_strainDofs(m), np6 = 6 * m->np;
  double* q = calloc((size_t)n, sizeof(double));
  double* eta = calloc((size_t)n, sizeof(double));
  double* qs = calloc((size_t)n, sizeof(double));
  double* buf = calloc((size_t)np6 * 8, sizeof(double));
  csError err;
  csrStrainData* d = csr_strainDataCreate(m, &err);
  if (!q || !eta || !qs || !buf || !d) {
    CS_EXPECT(0);
    free(q);
    free(eta);
    free(qs);
    free(buf);
    csr_strainDataDestroy(d);
    return;
  }
  double *V = buf, *A = buf + np6, *Vt = buf + 2 * np6, *Vp = buf + 3 * np6,
         *Vm = buf + 4 * np6, *D1 = buf + 5 * np6, *D2 = buf + 6 * np6, *Ak = buf + 7 * np6;
  double emax = 0;
  for (int j = 0; j < n; j++) {
    /* bending and twist ~0.02/mm x scale, stretch and shear ~0.05 x scale (test_strain_model's
     * bent rod); rates of a few per second on each */
    q[j] = scale * (j % 7 - 3) * (m->dcomp[j] <= CSR_STRAIN_TW ? 0.007 : 0.02);
    eta[j] = ((j * 5) % 11 - 5) * (m->dcomp[j] <= CSR_STRAIN_TW ? 0.01 : 0.03);
    emax = fmax(emax, fabs(eta[j]) * m->dscale[j]);
  }
  const double Vb[6] = {0.3, -0.2, 0.5, 40, -25, 10}; /* rad/s, mm/s */
  csr_strainTwistRates_(m, q, eta, Vb, NULL, V, A);
  csr_strainTwists_(m, q, eta, Vb, Vt);
  *same = memcmp(V, Vt, (size_t)np6 * sizeof(double)) == 0;
  /* on the kinematics' steps at q (Vt: scratch) */
  csr_strainSetQ(m, d, q);
  csr_strainKinematics_(m, d, 1);
  const double* ks = csr_strainStepsAt_(m, d);
  CS_EXPECT(ks != NULL);
  csr_strainTwistRates_(m, q, eta, Vb, ks, Vt, Ak);
  /* Richardson on ε = 1e-3 / emax and its half: truncation O(ε⁴) (~1e-12 relative at these
   * strains: ε emax is the largest strain change, ~1e-3 rad over a piece), cancellation
   * ~1e-16 |V| / ε ~ 1e-13 |V| */
  const double eps = 1e-3 / emax;
  difference(m, q, eta, Vb, eps, qs, Vp, Vm, D1);
  difference(m, q, eta, Vb, 0.5 * eps, qs, Vp, Vm, D2);
  double amax = 0, dd = 0, dk = 0;
  for (int i = 0; i < np6; i++) {
    const double ref = (4 * D2[i] - D1[i]) / 3;
    amax = fmax(amax, fabs(ref));
    dd = fmax(dd, fabs(A[i] - ref));
    dk = fmax(dk, fabs(Ak[i] - ref));
    D2[i] = ref;
  }
  /* the production difference (robot_strain_dyn.c: ε = 1e-6 / emax) */
  difference(m, q, eta, Vb, 1e-6 / emax, qs, Vp, Vm, D1);
  double d_old = 0;
  for (int i = 0; i < np6; i++) {
    d_old = fmax(d_old, fabs(D1[i] - D2[i]));
  }
  *e = dd / amax;
  *e_ks = dk / amax;
  *e_old = d_old / amax;
  /* the Zanna steps' |ω| */
  *thmax = 0;
  for (int k = 0; k < m->npiece; k++) {
    if (m->rigid[k]) {
      continue;
    }
    const double h = m->piece[k].length / m->nsub[k];
    for (int i = 0; i < m->nsub[k]; i++) {
      double Om[6];
      csr_strainMagnus_(m, q, k, i * h, h, Om, NULL);
      *thmax = fmax(*thmax, sqrt(csu_dot3(Om, Om)));
    }
  }
  /* another q: the steps are not offered, nor after the chain points' poses alone there (the
   * midpoints' steps would be q's), but after the whole kinematics there */
  qs[0] = q[0] + 1e-3;
  csr_strainSetQ(m, d, qs);
  *guard = ks != NULL && csr_strainStepsAt_(m, d) == NULL;
  csr_strainKinematics_(m, d, 3);
  *guard = *guard && csr_strainStepsAt_(m, d) == NULL;
  csr_strainKinematics_(m, d, 0);
  *guard = *guard && csr_strainStepsAt_(m, d) == d->ks;
  free(q);
  free(eta);
  free(qs);
  free(buf);
  csr_strainDataDestroy(d);
}


static void velocity_products_match_differences(void) {
  csrStrainModel* rods[2] = {bentRod(), legLayout()};
  const char* what[2] = {"bent three-piece rod", "leg layout"};
  const double scales[3] = {0.01, 0.1, 1.0};
  for (int r = 0; r < 2; r++) {
    if (!rods[r]) {
      continue;
    }
    for (int s = 0; s < 3; s++) {
      double e = 1, e_ks = 1, e_old = 1, th = 0;
      int same = 0, guard = 0;
      ratesCase(rods[r], scales[s], &e, &e_ks, &e_old, &th, &same, &guard);
      printf("  %s, strains x %.2f (largest step |w| %.3f rad): rates %.2e, on the kinematics' "
             "steps %.2e, production difference %.2e (of the largest rate)\n",
             what[r], scales[s], th, e, e_ks, e_old);
      /* the reference's own error (Richardson truncation ~1e-12, cancellation ~1e-13 of the
       * largest rate, ratesCase) bounds what this can see; 1e-9 leaves room for the largest
       * rate being smaller than |V| / piece length at the smallest strains */
      CS_EXPECT(e < 1e-11);
      CS_EXPECT(e_ks < 1e-11);
      CS_EXPECT(guard);
      CS_EXPECT(same);
    }
    csr_strainModelDestroy(rods[r]);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(velocity_products_match_differences);
  return cs_testSummary();
}
