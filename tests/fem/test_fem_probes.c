/* test_fem_probes.c: the calibration's stiffness probes reduced to EI and EA per segment
 * (csf_calibrationReduceProbes) on synthetic rows whose response is known in closed form:
 *  - a straight leg: a tip force F e1 bends segment s by S F a_s / EI (a_s the arm from its
 *    centre to the tip), F e3 stretches it by F / EA: the reduction returns EI and EA exactly;
 *  - the same responses with a segment turned by 90 deg (its tangent across e3) or a tip level
 *    with a segment's centre and beside it (the moment is torsion) or just above it (a short
 *    arm): that segment's value is NaN, the others are kept;
 *  - a failed probe gives NaN. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "fem_calibration.h"

#define EI_TRUE 3000.0 /* N mm^2 */
#define EA_TRUE 150.0  /* N */
#define F_BEND 0.005   /* N */
#define F_AXIAL 0.05   /* N */

/* a straight leg along e3: segment s from z0[s] over S[s], frames the identity */
static void straightRow(const csrActuator* act, csfBendRow* row, double z0[3]) {
  memset(row, 0, sizeof *row);
  double z = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    z0[s] = z;
    csfSegmentState* st = row->seg + s;
    st->stretch = 1;
    st->ca[2] = z;
    st->Ra[0] = st->Ra[4] = st->Ra[8] = 1;
    z += act->S[s] + (s < CSR_NSEG - 1 ? act->LS[s] : 0);
  }
  row->tip[2] = z;
  row->nprobe = 3;
  const double F[3][3] = {{F_BEND, 0, 0}, {0, F_BEND, 0}, {0, 0, F_AXIAL}};
  memcpy(row->probe_force, F, sizeof F);
}

/* the probed states of a linear segment with EI_TRUE, EA_TRUE under the row's probe forces */
static void respond(const csrActuator* act, csfBendRow* row) {
  for (int k = 0; k < 3; k++) {
    row->probe_ok[k] = 1;
    for (int s = 0; s < CSR_NSEG; s++) {
      const csfSegmentState* st = row->seg + s;
      csfSegmentState* q = &row->probe_seg[k][s];
      *q = *st;
      const double S = act->S[s];
      /* moment about the segment centre (straight, frame the identity: xc = ca + S/2 e3) */
      const double arm[3] = {row->tip[0] - st->ca[0], row->tip[1] - st->ca[1],
                             row->tip[2] - st->ca[2] - 0.5 * S};
      const double* F = row->probe_force[k];
      const double M[3] = {arm[1] * F[2] - arm[2] * F[1], arm[2] * F[0] - arm[0] * F[2],
                           arm[0] * F[1] - arm[1] * F[0]};
      q->bend[0] += S * M[1] / EI_TRUE;
      q->bend[1] += -S * M[0] / EI_TRUE;
      q->stretch += F[2] / EA_TRUE;
    }
  }
}


static void test_straight_leg_gives_the_closed_form(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "leg", &err) == CS_OK);
  csfBendRow row;
  double z0[3], EI[3][2], EA[3];
  straightRow(&act, &row, z0);
  respond(&act, &row);
  csf_calibrationReduceProbes(&act, &row, EI, EA);
  for (int s = 0; s < CSR_NSEG; s++) {
    /* the reduction's formula is the inverse of respond's: round-off only */
    CS_EXPECT_NEAR(EI[s][0], EI_TRUE, 0, 1e-12);
    CS_EXPECT_NEAR(EI[s][1], EI_TRUE, 0, 1e-12);
    CS_EXPECT_NEAR(EA[s], EA_TRUE, 0, 1e-12);
  }
  /* a failed probe: NaN for that direction only */
  row.probe_ok[1] = 0;
  csf_calibrationReduceProbes(&act, &row, EI, EA);
  CS_EXPECT(isnan(EI[0][1]) && isfinite(EI[0][0]) && isfinite(EA[0]));
}


static void test_probe_in_another_mode_is_skipped(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "leg", &err) == CS_OK);
  csfBendRow row;
  double z0[3], EI[3][2], EA[3];
  /* segment II2 turned by 90 deg about e2 (its axis along e1): the e3 probe pulls across it */
  straightRow(&act, &row, z0);
  csfSegmentState* st = row.seg + 1;
  memset(st->Ra, 0, sizeof st->Ra);
  st->Ra[2] = 1, st->Ra[4] = 1, st->Ra[6] = -1; /* columns: e1' = -e3, e2' = e2, e3' = e1 */
  respond(&act, &row);
  csf_calibrationReduceProbes(&act, &row, EI, EA);
  CS_EXPECT(isnan(EA[1]));
  CS_EXPECT_NEAR(EA[0], EA_TRUE, 0, 1e-12);
  CS_EXPECT_NEAR(EA[2], EA_TRUE, 0, 1e-12);
  /* the tip beside II3's centre, level with it: the e1 probe twists II3 (and bends II1, II2) */
  straightRow(&act, &row, z0);
  row.tip[0] = 0, row.tip[1] = 30, row.tip[2] = z0[2] + 0.5 * act.S[2];
  respond(&act, &row);
  csf_calibrationReduceProbes(&act, &row, EI, EA);
  CS_EXPECT(isnan(EI[2][0]));
  CS_EXPECT_NEAR(EI[0][0], EI_TRUE, 0, 1e-12);
  /* the tip 5 mm above II3's centre, on its axis: an arm below S/4, the moment's change across
   * the segment is larger than its centre value */
  straightRow(&act, &row, z0);
  row.tip[2] = z0[2] + 0.5 * act.S[2] + 5;
  respond(&act, &row);
  csf_calibrationReduceProbes(&act, &row, EI, EA);
  CS_EXPECT(isnan(EI[2][0]) && isnan(EI[2][1]));
  CS_EXPECT_NEAR(EI[1][0], EI_TRUE, 0, 1e-12);
  CS_EXPECT_NEAR(EA[2], EA_TRUE, 0, 1e-12);
}


int main(void) {
  CS_RUN(test_straight_leg_gives_the_closed_form);
  CS_RUN(test_probe_in_another_mode_is_skipped);
  return cs_testSummary();
}
