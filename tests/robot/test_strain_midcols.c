/* test_strain_midcols.c: backward Euler's step start by the recursion reads a midpoint's
 * Jacobian through its own piece's columns alone (the commit's kinematics want_J 4,
 * robot/strain/robot_strain_lie.c; assemble, robot_strain_dyn.c: the step force's share on
 * the earlier columns through the chain point before it), and so does the dense start's
 * inertia (csr_strainInertiaFrom_'s composite inertias read the chain points' Jacobians and
 * the midpoints' own columns); docs/notes/strain_leg.md, legpass19.
 *
 * Cases:
 *  - midpoint_columns_are_enough: a dense robot (artic 0, whose kinematics are always whole)
 *    runs 5 ms steps from standing (touch-down, the first strides); before each step a robot
 *    at artic 1 (swing legs by the recursion on want_J 4, touching legs by the dense path)
 *    and a dense one take its state, the artic 1 robot's midpoints' earlier columns (those
 *    want_J 4 leaves out) set to NaN in d->J and d->J0, and every leg prepares both ways. Z and
 *    ρ must be finite (a read of a column the pass did not form gives NaN) and the dense
 *    path's to 1e-9 relative (measured 2.9e-14 swing, 1.2e-13 touching: sums of ~40
 *    unknowns' products regrouped; a wrong block or transport is O(1)). Then one iterate both
 *    ways at the same base move on each touching leg: Z, ρ finite and within the same bound
 *    (8.3e-12). The midpoints' share on the earlier columns left out fails it (swing 6.2e-4,
 *    touching 9.3e-2). */
#include "cs_test.h"
#include "strain_test_robot.h"

/* the robot on the flat road at artic a (the defaults otherwise: backward Euler, n 36) */
static StrainRobot* robotAt(int a) {
  csrStrainParams sp = csr_strainDefaultParams();
  sp.artic = a;
  return strainRobotNew(&sp);
}


/* NaN into the midpoints' columns before their piece's (those want_J 4 leaves out), in J */
static void poisonMidpoints(const csrStrainModel* m, double* J) {
  const int n = m->n;
  for (int k = 0; k < m->npiece; k++) {
    for (int p = m->pt0[k] + 1; p < m->pt0[k + 1]; p += 2) {
      for (int r = 0; r < 6; r++) {
        for (int c = 0; c < m->dof0[k]; c++) {
          J[(size_t)p * 6 * n + (size_t)r * n + c] = NAN;
        }
      }
    }
  }
}


static void midpoint_columns_are_enough(void) {
  csError err;
  cs_errorClear(&err);
  char gp[1024];
  snprintf(gp, sizeof gp, "%s/gaits/flat_road.csv", getenv("CS_SOURCE_DIR"));
  csgGait* g = csg_gaitRead(gp, NULL, &err);
  StrainRobot* ref = robotAt(0);
  StrainRobot* a = robotAt(1);
  StrainRobot* b = robotAt(0);
  if (!g || !ref || !a || !b) {
    CS_EXPECT(0);
    return;
  }
  const double h = 5e-3;
  double* y0 = calloc((size_t)strainRobotStateSize(ref), sizeof(double));
  int nswing = 0, ntouch = 0, nit = 0, fin = 1;
  double ws = 0, wt = 0, wi = 0;
  for (int i = 0; i < 40; i++) {
    double p96[96];
    strainRobotSameStart(ref, a, b, g, (i + 1) * h, y0, p96);
    for (int k = 0; k < CSR_NLEG; k++) {
      const csrStrainModel* m = a->m[k];
      csrStrainData* da = a->d[k];
      csrStrainData* db = b->d[k];
      poisonMidpoints(m, da->J);
      poisonMidpoints(m, da->J0);
      double Za[36], ra[6], Zb[36], rb[6];
      CS_EXPECT(strainRobotPrepareBoth(a, b, k, p96, h, Za, ra, Zb, rb) == 0);
      fin &= strainFinite(Za, 36) && strainFinite(ra, 6);
      const double w = fmax(cs_relDiff(Zb, Za, 36), cs_relDiff(rb, ra, 6));
      if (db->ntouch == 0) {
        nswing++;
        ws = fmax(ws, w);
        continue;
      }
      ntouch++;
      wt = fmax(wt, w);
      const double dV[6] = {1e-3, -2e-3, 1.5e-3, 0.4, -0.3, 0.2};
      double Zka[36], rka[6], Zkb[36], rkb[6];
      CS_EXPECT(csr_strainUpdate(m, da, dV, NULL, NULL) == 0);
      CS_EXPECT(csr_strainUpdate(b->m[k], db, dV, NULL, NULL) == 0);
      CS_EXPECT(csr_strainIterate(m, da, Zka, rka) == 0);
      CS_EXPECT(csr_strainIterate(b->m[k], db, Zkb, rkb) == 0);
      fin &= strainFinite(Zka, 36) && strainFinite(rka, 6);
      nit++;
      wi = fmax(wi, fmax(cs_relDiff(Zkb, Zka, 36), cs_relDiff(rkb, rka, 6)));
    }
    long st = 0;
    CS_EXPECT(strainRobotAdvance(ref, g, i * h, (i + 1) * h, 16, 1e-9, 4, y0, &st, NULL, NULL,
                                 NULL, NULL) == 0);
  }
  printf("  40 steps of 5 ms from standing: %d swing starts (recursion) Z, rho within %.2e; "
         "%d touching starts (dense) %.2e, their iterates %.2e (relative to the dense "
         "robot's); every Z, rho finite: %s\n", nswing, ws, ntouch, wt, wi, fin ? "yes" : "NO");
  CS_EXPECT(nswing > 100 && ntouch > 100 && nit == ntouch);
  CS_EXPECT(fin);
  CS_EXPECT(ws < 1e-9 && wt < 1e-9 && wi < 1e-9);
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
  CS_RUN(midpoint_columns_are_enough);
  return cs_testSummary();
}
