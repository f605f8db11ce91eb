/* test_strain_keptnoj.c: backward Euler's touching iterate that keeps its matrix forms its
 * contact loads without the chain points' Jacobians (robot/strain/robot_strain_dyn.c
 * iterateAt: the twists by csr_strainChainTwistsNoJ_, Sᵀ L by csr_strainChainProjectNoJ_'s
 * adjoint sweep, robot_strain_lie.c); only an iterate that refactors forms them
 * (docs/notes/strain_leg.md, kept20).
 *
 * Cases:
 *  - kept_iterates_read_no_jacobian: a robot at the defaults runs 5 ms steps from standing
 *    (touch-down, the first strides); before each step two default robots take its state and
 *    every touching leg prepares and takes two iterates (base moves dV, dV / 4) both ways: on
 *    robot a with the chain points' Jacobian columns (what want_J 2 forms) set to NaN in d->J
 *    before each iterate, on robot b with them formed at the iterate's q first (want_J 2:
 *    the path that reads them). a's Z, ρ must be finite (a read of the poisoned columns gives
 *    NaN) and b's to 1e-9 relative (the sweep regroups the sums of J_pᵀ F_p and J_p η:
 *    round-off of ~40 products; a wrong transport or column is O(1)); a kept iterate of a
 *    must leave the Jacobians unformed (kin_chain 0), and most touching iterates keep. */
#include "cs_test.h"
#include "strain_test_robot.h"

/* NaN into the chain points' columns that want_J 2 forms (below pcol[p]) */
static void poisonChain(const csrStrainModel* m, double* J) {
  const int n = m->n;
  for (int p = 2; p < m->np; p += 2) {
    for (int r = 0; r < 6; r++) {
      for (int c = 0; c < m->pcol[p]; c++) {
        J[(size_t)p * 6 * n + (size_t)r * n + c] = NAN;
      }
    }
  }
}


static void kept_iterates_read_no_jacobian(void) {
  csError err;
  cs_errorClear(&err);
  char gp[1024];
  snprintf(gp, sizeof gp, "%s/gaits/flat_road.csv", getenv("CS_SOURCE_DIR"));
  csgGait* g = csg_gaitRead(gp, NULL, &err);
  csrStrainParams sp = csr_strainDefaultParams();
  StrainRobot* ref = strainRobotNew(&sp);
  StrainRobot* a = strainRobotNew(&sp);
  StrainRobot* b = strainRobotNew(&sp);
  if (!g || !ref || !a || !b) {
    CS_EXPECT(0);
    return;
  }
  const double h = 5e-3;
  double* y0 = calloc((size_t)strainRobotStateSize(ref), sizeof(double));
  int nit = 0, nkept = 0, fin = 1, formed = 0;
  double wi = 0;
  for (int i = 0; i < 40; i++) {
    double p96[96];
    strainRobotSameStart(ref, a, b, g, (i + 1) * h, y0, p96);
    for (int k = 0; k < CSR_NLEG; k++) {
      const csrStrainModel* m = a->m[k];
      csrStrainData* da = a->d[k];
      csrStrainData* db = b->d[k];
      double Za[36], ra[6], Zb[36], rb[6];
      CS_EXPECT(strainRobotPrepareBoth(a, b, k, p96, h, Za, ra, Zb, rb) == 0);
      if (db->ntouch == 0) {
        continue;
      }
      for (int it = 0; it < 2; it++) {
        const double f = it == 0 ? 1 : 0.25;
        const double dV[6] = {1e-3 * f, -2e-3 * f, 1.5e-3 * f, 0.4 * f, -0.3 * f, 0.2 * f};
        CS_EXPECT(csr_strainUpdate(m, da, dV, NULL, NULL) == 0);
        CS_EXPECT(csr_strainUpdate(b->m[k], db, dV, NULL, NULL) == 0);
        poisonChain(m, da->J);
        csr_strainKinematics_(b->m[k], db, 2);
        const int reuse = da->nreuse;
        CS_EXPECT(csr_strainIterate(m, da, Za, ra) == 0);
        CS_EXPECT(csr_strainIterate(b->m[k], db, Zb, rb) == 0);
        fin &= strainFinite(Za, 36) && strainFinite(ra, 6);
        nit++;
        if (da->nreuse > reuse) {
          nkept++;
          formed += da->kin_chain; /* a kept iterate that formed them anyway */
        }
        wi = fmax(wi, fmax(cs_relDiff(Zb, Za, 36), cs_relDiff(rb, ra, 6)));
      }
    }
    long st = 0;
    CS_EXPECT(strainRobotAdvance(ref, g, i * h, (i + 1) * h, 16, 1e-9, 4, y0, &st, NULL, NULL,
                                 NULL, NULL) == 0);
  }
  printf("  40 steps of 5 ms from standing: %d touching iterates, %d kept (%d of those formed "
         "the chain Jacobians); Z, rho within %.2e of the Jacobians' path; every Z, rho "
         "finite: %s\n", nit, nkept, formed, wi, fin ? "yes" : "NO");
  CS_EXPECT(nit > 100 && nkept > 100);
  CS_EXPECT(formed == 0);
  CS_EXPECT(fin);
  CS_EXPECT(wi < 1e-9);
  free(y0);
  strainRobotDestroy(ref);
  strainRobotDestroy(a);
  strainRobotDestroy(b);
  free(ref);
  free(a);
  free(b);
  csg_gaitDestroy(g);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(kept_iterates_read_no_jacobian);
  return cs_testSummary();
}
