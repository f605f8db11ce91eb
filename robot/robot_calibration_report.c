/* robot_calibration_report.c: the calibration model against a table's cases (the errors of
 * fitted, held-out and symmetry cases, with the constant-curvature kinematics of the leg), and
 * reports of them (robot_calibration_model.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "robot_analytic.h"
#include "robot_calibration_internal.h"

/* the held-out target of issue 8: 5 % of the bend angle or 1 deg, 2 % of the leg length */
#define TARGET_BEND_REL 0.05
#define TARGET_BEND_ABS (1.0 * CS_DEG)
#define TARGET_TIP_REL 0.02

/* ---- comparison with a case ---------------------------------------------------------------- */

csStatus csr_calModelCompare(const csrCalModel* m, const csrCalCase* c, csrCalCompare* out,
                             csError* err) {
  memset(out, 0, sizeof *out);
  if (c->kind == CSR_CAL_GRAVITY) {
    return cs_errorSet(err, CS_ERR_ARG, "case %s: a gravity case has no chamber pattern",
                       c->name);
  }
  out->bend_deg = -1;
  const double L = csr_actuatorLength(&m->leg);
  for (int i = 0; i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
    const double p = c->pressure[i];
    csrSegmentStrain sm[CSR_NSEG], sf[CSR_NSEG];
    memset(sm, 0, sizeof sm);
    memset(sf, 0, sizeof sf);
    for (int s = 0; s < CSR_NSEG; s++) {
      const double P[4] = {c->ratio[0] * p, c->ratio[1] * p, c->ratio[2] * p, c->ratio[3] * p};
      csrCalSegment q;
      if (csr_calModelEval(m, s, P, &q) != 0) {
        return cs_errorSet(err, CS_ERR_SOLVER, "case %s: the model fails at %g MPa", c->name, p);
      }
      const double* bf = c->bend + 6 * i + 2 * s;
      const double d = hypot(q.bend[0] - bf[0], q.bend[1] - bf[1]), mag = hypot(bf[0], bf[1]);
      const double score = d / fmax(TARGET_BEND_REL * mag, TARGET_BEND_ABS);
      if (d / CS_DEG > out->bend_deg) {
        out->bend_deg = d / CS_DEG, out->bend_at_p = p, out->bend_at_seg = s;
        out->bend_fe_deg = mag / CS_DEG;
      }
      out->bend_score = fmax(out->bend_score, score);
      out->stretch = fmax(out->stretch, fabs(q.stretch - c->stretch[3 * i + s]));
      const double S = m->leg.S[s];
      sm[s].lambda0 = q.stretch, sm[s].kappa[0] = -q.bend[0] / S, sm[s].kappa[1] = -q.bend[1] / S;
      sf[s].lambda0 = c->stretch[3 * i + s];
      sf[s].kappa[0] = -bf[0] / S, sf[s].kappa[1] = -bf[1] / S;
    }
    double tm[3], tf[3];
    if (csr_ccForwardKinematics(&m->leg, sm, 1, NULL, tm, NULL, err) != CS_OK ||
        csr_ccForwardKinematics(&m->leg, sf, 1, NULL, tf, NULL, err) != CS_OK) {
      return cs_errorSet(err, CS_ERR_SOLVER, "case %s: kinematics fail at %g MPa", c->name, p);
    }
    const double* tip = c->tip + 3 * i;
    const double dt[3] = {tm[0] - tip[0], tm[1] - tip[1], tm[2] - tip[2]};
    const double dc[3] = {tf[0] - tip[0], tf[1] - tip[1], tf[2] - tip[2]};
    out->tip_mm = fmax(out->tip_mm, csu_norm3(dt));
    out->tip_cc_mm = fmax(out->tip_cc_mm, csu_norm3(dc));
    out->tip_score = fmax(out->tip_score, csu_norm3(dt) / (TARGET_TIP_REL * L));
    out->rows++;
    out->p_last = p;
  }
  if (out->rows == 0) {
    out->bend_deg = 0;
    return cs_errorSet(err, CS_ERR_RANGE, "case %s: no row within the model's range", c->name);
  }
  return CS_OK;
}
