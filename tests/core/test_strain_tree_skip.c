/* test_strain_tree_skip.c: legs not re-passed in the tree step's Newton passes
 * (csOptions.tree_skip, core/sim_tree.c "Legs not re-passed"), on the flat road as the scene
 * sets it up (strain legs, adaptive step at its default 2.5e-4 mm, from the settled robot):
 *  - the option keeps contact-free legs' linearisations (a positive count) and the step stays
 *    the same step: every try takes as many passes and the adaptive step the same steps, and
 *    the support's and every leg's state after 0.3 s of the gait differ from the run that
 *    re-linearises every leg by less than tree_tol per try taken (each try's converged step the
 *    same within tree_tol: the bound adds them up);
 *  - a kept leg that would be wrong is caught: a leg type that claims to be contact-free
 *    during the passes (so the driver keeps stance legs' linearisations too) has its steps
 *    rejected at the finish, where a kept leg touches at the step's end (the count of such
 *    rejections is positive);
 *  - with the option at 0 nothing is kept (the count stays 0: the first test's reference run).
 * ~0.3 s settling and 0.3 s of gait per data at 5 ms macro steps: a few seconds in release. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "strain_flat_fixture.h"
#include "sim_model.h"

static char g_src[512];

/* 0.3 s of the gait in 5 ms macro steps */
enum { NSTEP = 60 };


static void test_tree_skip_keeps_the_step(void) {
  csModel m;
  CS_EXPECT(csTestLoadFlatStrain(&m, g_src, &csr_leg_strain, 5e-3, 2, 1, 2.5e-4));
  csData* a = csTestSettledData(&m);
  csData* b = csTestSettledData(&m);
  if (!a || !b) {
    cs_dataDestroy(a);
    cs_dataDestroy(b);
    cs_modelDestroy(&m);
    return;
  }
  const long pa0 = cs_treePassCount(a), pb0 = cs_treePassCount(b);
  const long sa0 = cs_stepCount(a);
  CS_EXPECT(csTestStepN(&m, a, NSTEP));
  CS_EXPECT(cs_treeSkipCount(a) == 0);
  m.opt.tree_skip = 0.1; /* read at every step: b's steps keep contact-free legs */
  CS_EXPECT(csTestStepN(&m, b, NSTEP));
  const long skipped = cs_treeSkipCount(b);
  const long tries = cs_treePassCount(a) - pa0;
  printf("  %ld passes without, %ld with tree_skip 0.1; %ld leg linearisations kept, %ld "
         "tries rejected for a kept leg's landing\n", tries, cs_treePassCount(b) - pb0, skipped,
         cs_treeCaughtCount(b));
  CS_EXPECT(skipped > 0);
  CS_EXPECT(cs_treePassCount(b) - pb0 == tries);
  CS_EXPECT(cs_stepCount(b) == cs_stepCount(a) && cs_stepCount(a) > sa0);
  CS_EXPECT(cs_treeCaughtCount(b) == 0);
  /* the support's displacement (mm) against the bound; every state entry (poses, twists,
   * strains, rates, anchors) relative to 1 + |entry| printed beside it (rates are moves per h:
   * no bound of tree_tol's units) */
  const int n = cs_stateSize(&m, a);
  double* x = malloc(2 * (size_t)n * sizeof(double));
  CS_EXPECT(x != NULL);
  if (x) {
    cs_stateGet(&m, a, x);
    cs_stateGet(&m, b, x + n);
    double worst = 0;
    for (int i = 0; i < n; i++) {
      worst = fmax(worst, fabs(x[i] - x[n + i]) / (1 + fabs(x[i])));
    }
    double pa[3], pb[3];
    cs_supportDisplacement(a, pa);
    cs_supportDisplacement(b, pb);
    const double dx = fmax(fabs(pa[0] - pb[0]), fmax(fabs(pa[1] - pb[1]), fabs(pa[2] - pb[2])));
    /* each try's step the same within tree_tol (a move, mm): over the tries' count of steps */
    const double bound = (double)(cs_stepCount(a) - sa0) * m.opt.tree_tol;
    printf("  support displacement differs by %.3g mm (bound %.3g mm: tree_tol per step); "
           "every state entry within %.3g of 1 + |entry|\n", dx, bound, worst);
    CS_EXPECT(dx <= bound);
    free(x);
  }
  cs_dataDestroy(a);
  cs_dataDestroy(b);
  cs_modelDestroy(&m);
}


/* ---- a leg that claims to be contact-free during the passes --------------------------------
 * Its contactFree says 1 while a step is prepared (the driver then keeps stance legs'
 * linearisations too, whose contact moves within the passes) and the truth after the finish.
 * The flags are per leg, by the order prepare first sees them (test state, one run at a time). */
static csrLeg* g_legs[CSR_NLEG];
static int g_in_step[CSR_NLEG];
static long g_lies;

static int legIndex(const csrLeg* leg) {
  for (int k = 0; k < CSR_NLEG; k++) {
    if (g_legs[k] == leg) {
      return k;
    }
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    if (!g_legs[k]) {
      g_legs[k] = (csrLeg*)leg;
      return k;
    }
  }
  return -1;
}

static int preparePretending(csrLeg* leg, double h, const csrBaseState* b0, double Z[36],
                             double rho[6]) {
  const int k = legIndex(leg);
  if (k >= 0) {
    g_in_step[k] = 1;
  }
  return csr_leg_strain.prepare(leg, h, b0, Z, rho);
}

static int finishPretending(csrLeg* leg, const csrBaseState* b1, csrWrench* w) {
  const int k = legIndex(leg);
  if (k >= 0) {
    g_in_step[k] = 0;
  }
  return csr_leg_strain.finish(leg, b1, w);
}

static int contactFreePretending(const csrLeg* leg) {
  const int k = legIndex(leg);
  const int truth = csr_leg_strain.contactFree(leg);
  if (k >= 0 && g_in_step[k]) {
    g_lies += !truth;
    return 1;
  }
  return truth;
}


static void test_tree_skip_catches_a_kept_leg_that_touches(void) {
  csrLegType pretending = csr_leg_strain;
  pretending.prepare = preparePretending;
  pretending.finish = finishPretending;
  pretending.contactFree = contactFreePretending;
  memset(g_legs, 0, sizeof g_legs);
  memset(g_in_step, 0, sizeof g_in_step);
  g_lies = 0;
  csModel m;
  CS_EXPECT(csTestLoadFlatStrain(&m, g_src, &pretending, 5e-3, 2, 1, 2.5e-4));
  csData* d = csTestSettledData(&m);
  if (!d) {
    cs_modelDestroy(&m);
    return;
  }
  m.opt.tree_skip = 0.1;
  const long r0 = cs_rejectCount(d);
  csError err;
  int steps = 0;
  /* until the first catch (the driver then retries the step smaller; whether the halves
   * converge is not this test's concern) */
  while (steps < NSTEP && cs_treeCaughtCount(d) == 0) {
    if (cs_step(&m, d, &err) != CS_OK) {
      break;
    }
    steps++;
  }
  printf("  %d macro steps, %ld passes where a touching leg claimed no contact, %ld tries "
         "rejected for a kept leg touching at the step's end, %ld rejected in all\n", steps,
         g_lies, cs_treeCaughtCount(d), cs_rejectCount(d) - r0);
  CS_EXPECT(g_lies > 0);
  CS_EXPECT(cs_treeCaughtCount(d) > 0);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


int main(int argc, char** argv) {
  csTestStrainInit(argc, argv, g_src, sizeof g_src);
  CS_RUN(test_tree_skip_keeps_the_step);
  CS_RUN(test_tree_skip_catches_a_kept_leg_that_touches);
  dCloseODE();
  return cs_testSummary();
}
