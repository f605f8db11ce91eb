/* robot_gaitdesign.c: gait pressures from the calibrated leg model (see robot_gaitdesign.h).
 * Both unknowns are found by bisection: the foot stroke and the segment bend grow
 * monotonically with pressure in every calibration map we have (test_analytic checks it for
 * the analytic model), and bisection needs nothing else. 60 halvings resolve 1 MPa to 1e-18. */
#include "robot_gaitdesign.h"

#include <math.h>
#include <string.h>

#include "robot_analytic.h"

enum { BISECTIONS = 60 };


csStatus csr_footFromPressures(const csrActuator* act, const csrBendMap* map,
                               const double p[CSR_NSEG * CSR_NCHAMBER], double foot[3],
                               csError* err) {
  csrSegmentStrain st[CSR_NSEG];
  memset(st, 0, sizeof st);
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2], stretch;
    if (map->eval(map->ctx, s, p + 4 * s, bend, &stretch) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER, "calibration map failed on segment %d", s + 1);
    }
    /* bend = -kappa S (robot_analytic.h): back to the stretch-gradient curvature; the prb
     * level ignores the stretch, so the designed motion does too */
    st[s].lambda0 = 1.0;
    st[s].kappa[0] = -bend[0] / act->S[s];
    st[s].kappa[1] = -bend[1] / act->S[s];
  }
  return csr_ccForwardKinematics(act, st, 1, NULL, foot, NULL, err);
}


/* pressures of the S-shape (stroke) at p, and of the crouch at (p, p2) */
static void shapeS(double p, double P[CSR_NSEG * CSR_NCHAMBER]) {
  memset(P, 0, sizeof(double) * CSR_NSEG * CSR_NCHAMBER);
  P[2] = P[3] = p; /* II1 Ω3&Ω4: bends towards +e1 */
  P[4] = P[5] = p; /* II2 Ω1&Ω2: bends towards -e1 */
}


static void shapeZ(double p, double p2, double P[CSR_NSEG * CSR_NCHAMBER]) {
  shapeS(p, P);
  P[4] = P[5] = p2;
  P[10] = P[11] = p; /* II3 Ω3&Ω4: back towards +e1 */
}


/* total bend angle (rad) of segment s under pressures P */
static double segmentAngle(const csrBendMap* map, int s, const double P[CSR_NCHAMBER]) {
  double bend[2], stretch;
  if (map->eval(map->ctx, s, P, bend, &stretch) != 0) {
    return NAN;
  }
  return hypot(bend[0], bend[1]);
}


csStatus csr_designFlatRoad(const csrActuator* act, const csrBendMap* map, double stroke,
                            double p_max, csrFlatRoadDesign* out, csError* err) {
  if (!(stroke > 0) || !(p_max > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "stroke and p_max must be > 0");
  }
  /* search no higher than the calibration reaches: the map refuses to extrapolate */
  const char* capped = p_max > map->p_max ? " (the calibration's range)" : "";
  p_max = fmin(p_max, map->p_max);
  double P[CSR_NSEG * CSR_NCHAMBER], foot[3], foot0[3];
  memset(P, 0, sizeof P);
  csStatus st = csr_footFromPressures(act, map, P, foot0, err);
  if (st != CS_OK) return st;
  shapeS(p_max, P);
  if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
  if (foot[0] - foot0[0] < stroke) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "a %.1f mm stroke needs more than %.3g MPa%s (reaches %.1f mm)", stroke,
                       p_max, capped, foot[0] - foot0[0]);
  }
  /* stroke: bisection on p */
  double lo = 0, hi = p_max;
  for (int i = 0; i < BISECTIONS; i++) {
    double mid = 0.5 * (lo + hi);
    shapeS(mid, P);
    if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
    if (foot[0] - foot0[0] < stroke) lo = mid; else hi = mid;
  }
  out->p_stroke = 0.5 * (lo + hi);
  shapeS(out->p_stroke, P);
  csr_footFromPressures(act, map, P, foot, err);
  out->stroke = foot[0] - foot0[0];
  out->lift_stroke = foot0[2] - foot[2];
  out->theta_stroke_deg = segmentAngle(map, 0, P) * 180 / 3.14159265358979323846;

  /* crouch: II2 bends twice the S-shape angle */
  double target = 2 * segmentAngle(map, 1, P + 4);
  double Q[CSR_NCHAMBER] = {p_max, p_max, 0, 0};
  if (!(segmentAngle(map, 1, Q) >= target)) {
    return cs_errorSet(err, CS_ERR_RANGE, "the crouch needs more than %.3g MPa%s in II2", p_max,
                       capped);
  }
  lo = out->p_stroke;
  hi = p_max;
  for (int i = 0; i < BISECTIONS; i++) {
    double mid = 0.5 * (lo + hi);
    Q[0] = Q[1] = mid;
    if (segmentAngle(map, 1, Q) < target) lo = mid; else hi = mid;
  }
  out->p_crouch_II2 = 0.5 * (lo + hi);
  shapeZ(out->p_stroke, out->p_crouch_II2, P);
  if ((st = csr_footFromPressures(act, map, P, foot, err)) != CS_OK) return st;
  out->lift_crouch = foot0[2] - foot[2];
  out->crouch_offset = foot[0] - foot0[0];
  return CS_OK;
}
