/* test_strain_refactor.c: a stance leg's Newton iterate that refactors (a contact slot changed
 * its state) after the step started by the articulated recursion with the contact's blocks
 * (artic 2) takes the Woodbury update of the start's pieces' factors
 * (robot/strain/robot_strain_woodbury.c) instead of W_M's dense assembly and the n x n LU.
 *
 * Cases:
 *  - stance_refactor_is_the_dense_one: a dense robot (artic 0) runs 5 ms steps from standing
 *    (touch-down, the first strides); before each step an artic 2 and a dense robot take its
 *    state, and every leg that touches at the start prepares both ways and then iterates four
 *    times at the same base moves (shrinking 10x a pass, so the iterates after a refactor keep
 *    its matrix). Where both refactor, Z, ρ, X (W_ll⁻¹ W_lb) and y (W_ll⁻¹ h r_l) of the
 *    update against the dense LU's; where both keep the refactor's matrix, ρ and y of the
 *    update's solve against the dense solve. Bound 1e-9 relative: the start's recursion and the
 *    stance test beside it (test_strain_robot stance_condensation_is_the_dense_one) are
 *    ~1e-12 with the contact's stiffness; the update adds the capacitance's solve (its
 *    condition with one shape leaving and one entering measured below), a wrong block or sign
 *    is O(1). At the default basis (n 36) and at 3 modes, 4 sub-intervals (n 42). y's bound
 *    is 1e-8: its largest difference over the 345 refactors is the tail of the round-off the
 *    reference run's states carry (backward Euler, n 36: 9.5e-11 to 5.1e-10 with the velocity
 *    products' old central-difference step 0.7e-6 to 2e-6, 1.2e-9 with the exact products,
 *    bdf17 in docs/notes/strain_leg.md), while the perturbed block below moves it by 2.3e-5.
 *  - bdf2_refactor_is_the_dense_one: the same on the linearly implicit BDF2 the strain level
 *    runs (step_order 2, step_refresh 0): W_M is the prepare's extrapolated iterate's (or a
 *    refreshed iterate's), h = c2 h_step in the update's C as in the start's factor. The same
 *    bound (measured 2e-12 to 4.5e-12 over 190 refactors, 30-100x below backward Euler's
 *    here). The update given h_step instead of c2 h_step is O(100) off (tried).
 *  - stance_refactor_sees_a_perturbed_block: the same comparison with one entry of the start
 *    shape's A (the part the update removes; the start's factor already formed) scaled by
 *    1 + 1e-6 on the artic 2 robot, backward Euler and BDF2: the refactors' Z leaves the bound,
 *    so the comparisons above can fail. */
#include "cs_test.h"
#include "strain_test_robot.h"

typedef struct {
  int nref, nkept, nwb2;                 /* refactors compared, kept iterates after one, second
                                            refactors on an earlier update */
  double z, r, x, y, kr, ky;             /* largest relative differences */
} RefactorDiff;


/* the robot on the flat road at artic a, bend_order bend, nsub sub; order 2: the linearly
 * implicit BDF2 the strain level runs (step_order 2, step_refresh 0) */
static StrainRobot* robotAt(int a, int bend, int sub, int order) {
  csrStrainParams sp = csr_strainDefaultParams();
  sp.bend_order = bend;
  sp.nsub = sub;
  sp.artic = a;
  sp.step_order = order;
  sp.step_refresh = 0;
  return strainRobotNew(&sp);
}


static void robotFree(StrainRobot* r) {
  if (r) {
    strainRobotDestroy(r);
    free(r);
  }
}


static RefactorDiff refactorSame(int bend, int sub, int order, int perturb) {
  RefactorDiff o = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  csError err;
  cs_errorClear(&err);
  char gp[1024];
  snprintf(gp, sizeof gp, "%s/gaits/flat_road.csv", getenv("CS_SOURCE_DIR"));
  csgGait* g = csg_gaitRead(gp, NULL, &err);
  StrainRobot* r = robotAt(0, bend, sub, order); /* the reference's run */
  StrainRobot* a = robotAt(2, bend, sub, order);
  StrainRobot* b = robotAt(0, bend, sub, order);
  if (!g || !r || !a || !b) {
    CS_EXPECT(0);
    return o;
  }
  const double h = 5e-3;
  double* y0 = calloc((size_t)strainRobotStateSize(r), sizeof(double));
  for (int i = 0; i < 40 && y0; i++) {
    double p96[96];
    strainRobotSameStart(r, a, b, g, (i + 1) * h, y0, p96);
    for (int k = 0; k < CSR_NLEG; k++) {
      const csrStrainModel* m = a->m[k];
      csrStrainData* da = a->d[k];
      csrStrainData* db = b->d[k];
      const int n = m->n;
      double Za[36], ra[6], Zb[36], rb[6];
      CS_EXPECT(strainRobotPrepareBoth(a, b, k, p96, h, Za, ra, Zb, rb) == 0);
      if (db->ntouch == 0 || da->art_f != 1) {
        continue;
      }
      if (perturb) {
        int im = 0;
        for (int e = 1; e < 36; e++) {
          im = fabs(da->cA[e]) > fabs(da->cA[im]) ? e : im;
        }
        da->cA[im] *= 1 + 1e-6;
      }
      /* four iterates at base moves shrinking 10x a pass */
      const double dV0[6] = {1e-3, -2e-3, 1.5e-3, 0.4, -0.3, 0.2};
      double dV[6] = {0, 0, 0, 0, 0, 0}, s = 1;
      for (int it = 0; it < 4; it++, s *= 0.1) {
        for (int c = 0; c < 6; c++) {
          dV[c] += s * dV0[c];
        }
        const int wb_before = da->wb_f;
        if (csr_strainUpdate(m, da, dV, NULL, NULL) != 0 ||
            csr_strainUpdate(b->m[k], db, dV, NULL, NULL) != 0 ||
            csr_strainIterate(m, da, Za, ra) != 0 || csr_strainIterate(b->m[k], db, Zb, rb) != 0) {
          break;
        }
        const int refa = da->wb_f && da->nreuse == 0, refb = db->nreuse == 0;
        if (refa && refb) {
          o.nref++;
          o.nwb2 += wb_before;
          o.z = fmax(o.z, cs_relDiff(Zb, Za, 36));
          o.r = fmax(o.r, cs_relDiff(rb, ra, 6));
          o.x = fmax(o.x, cs_relDiff(db->X, da->X, 6 * n));
          o.y = fmax(o.y, cs_relDiff(db->y, da->y, n));
        } else if (da->wb_f && !refa && !refb) {
          o.nkept++;
          o.kr = fmax(o.kr, cs_relDiff(rb, ra, 6));
          o.ky = fmax(o.ky, cs_relDiff(db->y, da->y, n));
        }
        if (refa != refb) {
          break; /* the two paths took different decisions: compared no further */
        }
      }
    }
    long st = 0;
    CS_EXPECT(strainRobotAdvance(r, g, i * h, (i + 1) * h, 16, 1e-9, 4, y0, &st, NULL, NULL,
                                 NULL, NULL) == 0);
  }
  printf("  %s, bend_order %d, sub %d (n %d)%s: %d refactoring iterates (%d on an earlier "
         "update): Z %.2e, rho %.2e, X %.2e, y %.2e; %d kept iterates after them: rho %.2e, "
         "y %.2e (relative)\n",
         order == 2 ? "BDF2" : "backward Euler", bend, sub, a->m[0]->n,
         perturb ? ", the start shape's A perturbed by 1e-6" : "", o.nref,
         o.nwb2, o.z, o.r, o.x, o.y, o.nkept, o.kr, o.ky);
  free(y0);
  robotFree(r);
  robotFree(a);
  robotFree(b);
  csg_gaitDestroy(g);
  return o;
}


/* the update against the dense LU at step_order `order`, the default basis (n 36) and 3 modes,
 * 4 sub (n 42) */
static void expectDense(int order) {
  const int cfg[2][2] = {{1, 2}, {2, 4}};
  for (int c = 0; c < 2; c++) {
    const RefactorDiff o = refactorSame(cfg[c][0], cfg[c][1], order, 0);
    CS_EXPECT(o.nref > 50);
    CS_EXPECT(o.nkept > 50);
    CS_EXPECT(o.z < 1e-9 && o.r < 1e-9 && o.x < 1e-9 && o.y < 1e-8);
    CS_EXPECT(o.kr < 1e-9 && o.ky < 1e-9);
  }
}


static void stance_refactor_is_the_dense_one(void) {
  expectDense(1);
}


static void bdf2_refactor_is_the_dense_one(void) {
  expectDense(2);
}


static void stance_refactor_sees_a_perturbed_block(void) {
  for (int order = 1; order <= 2; order++) {
    const RefactorDiff o = refactorSame(1, 2, order, 1);
    CS_EXPECT(o.nref > 50);
    CS_EXPECT(o.z > 1e-8);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(stance_refactor_is_the_dense_one);
  CS_RUN(bdf2_refactor_is_the_dense_one);
  CS_RUN(stance_refactor_sees_a_perturbed_block);
  return cs_testSummary();
}
