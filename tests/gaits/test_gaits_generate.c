/* test_gaits_generate.c: the flat-road gait generator writes the paper's sequence: ACFH and
 * BDEG alternate every period, II1 Ω3&Ω4 + II2 Ω1&Ω2 form the S-shape, II3 only in the crouch,
 * everything vents at the end, and the table lasts nstroke + 1 periods. */
#include <math.h>

#include "cs_test.h"
#include "gaits_generate.h"
#include "gaits_labels.h"

enum { A, B, C, D, E, F, G, H };


/* pressure of leg k, segment s (1..3), chamber j (1..4) in row r */
static double P(const csgGait* g, int r, int k, int s, int j) {
  return csg_gaitPressure(g, r, csg_labelFromTriple(k, s, j));
}


static void test_generate_paper_table(void) {
  csgFlatRoadSpec s = csg_defaultFlatRoadSpec();
  s.p_stroke = 0.15;
  csError err;
  csgGait* g = csg_generateFlatRoad(&s, &err);
  CS_EXPECT(g != NULL);
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_OK);
  /* rows at 0..8 s plus the end marker at 9 s */
  CS_EXPECT(g->nrow == 10);
  CS_EXPECT(g->time[0] == 0 && g->time[9] == 9);
  /* 0-1 s: ACFH S-shape (exact values written), BDEG vented */
  CS_EXPECT(P(g, 0, A, 1, 3) == 0.15 && P(g, 0, A, 1, 4) == 0.15);
  CS_EXPECT(P(g, 0, H, 2, 1) == 0.15 && P(g, 0, H, 2, 2) == 0.15);
  CS_EXPECT(P(g, 0, A, 1, 1) == 0 && P(g, 0, A, 3, 3) == 0 && P(g, 0, B, 1, 3) == 0);
  /* 1-2 s: swapped */
  CS_EXPECT(P(g, 1, A, 1, 3) == 0 && P(g, 1, B, 1, 3) == 0.15 && P(g, 1, E, 2, 2) == 0.15);
  /* 8 s: all vented, and the end marker repeats it */
  for (int lab = 1; lab <= CSG_NLABEL; lab++) {
    CS_EXPECT(csg_gaitPressure(g, 8, lab) == 0 && csg_gaitPressure(g, 9, lab) == 0);
  }
  csg_gaitDestroy(g);
}


static void test_generate_crouch_table(void) {
  csgFlatRoadSpec s = csg_defaultFlatRoadSpec();
  s.p_stroke = 0.15;
  s.p_crouch_II2 = 0.28;
  s.crouch = 1;
  csError err;
  csgGait* g = csg_generateFlatRoad(&s, &err);
  CS_EXPECT(g != NULL);
  /* row 1 at t = 1 s: BDEG crouch (II3 Ω3&Ω4 on, II2 at the crouch pressure), ACFH still S */
  CS_EXPECT(g->time[1] == 1.0);
  CS_EXPECT(P(g, 1, B, 3, 3) == 0.15 && P(g, 1, B, 2, 1) == 0.28 && P(g, 1, A, 2, 1) == 0.15);
  /* row 2 at t = 1 + t_land: ACFH vented, BDEG S-shape */
  CS_EXPECT(fabs(g->time[2] - (1.0 + s.t_land)) < 1e-12);
  CS_EXPECT(P(g, 2, A, 1, 3) == 0 && P(g, 2, B, 2, 1) == 0.15 && P(g, 2, B, 3, 3) == 0);
  CS_EXPECT(g->time[g->nrow - 1] == 9.0);
  csg_gaitDestroy(g);
}


static void test_generate_rejects_bad_spec(void) {
  csError err;
  csgFlatRoadSpec s = csg_defaultFlatRoadSpec();
  CS_EXPECT(csg_generateFlatRoad(&s, &err) == NULL); /* no pressure */
  s.p_stroke = 0.1;
  s.t_land = 1.5;
  CS_EXPECT(csg_generateFlatRoad(&s, &err) == NULL && err.status == CS_ERR_RANGE);
  s = csg_defaultFlatRoadSpec();
  s.p_stroke = 0.1;
  s.crouch = 1; /* crouch without its pressure */
  CS_EXPECT(csg_generateFlatRoad(&s, &err) == NULL);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_generate_paper_table);
  CS_RUN(test_generate_crouch_table);
  CS_RUN(test_generate_rejects_bad_spec);
  return cs_testSummary();
}
