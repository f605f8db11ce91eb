/* gaits_generate.c: the flat-road gait generator (see gaits_generate.h). */
#include "gaits_generate.h"

#include <math.h>
#include <string.h>

#include "gaits_labels.h"

/* legs of the two groups, 0..7 = A..H (paper Sec. 5.1) */
static const int kGroup[2][4] = {{0, 2, 5, 7}, {1, 3, 4, 6}}; /* ACFH, BDEG */

typedef enum { POSE_STRAIGHT, POSE_S, POSE_Z } Pose;


csgFlatRoadSpec csg_defaultFlatRoadSpec(void) {
  csgFlatRoadSpec s;
  s.nstroke = 8;
  s.period = 1.0;
  /* the crouch ramps over the first 0.2 s (default ramp) of a period; landing 0.15 s after it
   * has finished leaves the pneumatic lag (tau = 20 ms) time to settle */
  s.t_land = 0.35;
  s.t_final_vent = 0.8;
  s.p_stroke = 0;
  s.p_crouch_II2 = 0;
  s.crouch = 0;
  return s;
}


/* write one leg's pose into row r */
static void setPose(csgGait* g, int r, int leg, Pose pose, const csgFlatRoadSpec* s) {
  double P[3][4] = {{0}};
  if (pose == POSE_S || pose == POSE_Z) {
    P[0][2] = P[0][3] = s->p_stroke;                                   /* II1 Ω3&Ω4 */
    P[1][0] = P[1][1] = (pose == POSE_Z) ? s->p_crouch_II2 : s->p_stroke; /* II2 Ω1&Ω2 */
  }
  if (pose == POSE_Z) {
    P[2][2] = P[2][3] = s->p_stroke; /* II3 Ω3&Ω4 */
  }
  for (int seg = 0; seg < 3; seg++) {
    for (int j = 0; j < 4; j++) {
      csg_gaitSetPressure(g, r, csg_labelFromTriple(leg, seg + 1, j + 1), P[seg][j], NULL);
    }
  }
}


static void setGroup(csgGait* g, int r, int group, Pose pose, const csgFlatRoadSpec* s) {
  for (int i = 0; i < 4; i++) {
    setPose(g, r, kGroup[group][i], pose, s);
  }
}


/* append a row at time t with the two groups' poses */
static int addRow(csgGait* g, double t, Pose g0, Pose g1, const csgFlatRoadSpec* s,
                  csError* err) {
  int r = g->nrow;
  if (csg_gaitSetRowCount(g, r + 1, err) != CS_OK || csg_gaitSetTime(g, r, t, err) != CS_OK) {
    return 0;
  }
  setGroup(g, r, 0, g0, s);
  setGroup(g, r, 1, g1, s);
  return 1;
}


csgGait* csg_generateFlatRoad(const csgFlatRoadSpec* s, csError* err) {
  if (s->nstroke < 1 || s->nstroke > 1000 || !(s->period > 0) || !(s->t_land > 0) ||
      !(s->t_land < s->period) || !(s->t_final_vent > s->t_land) ||
      !(s->t_final_vent < s->period) || !(s->p_stroke > 0) ||
      (s->crouch && !(s->p_crouch_II2 > 0))) {
    cs_errorSet(err, CS_ERR_RANGE,
                "flat-road gait: need 1..1000 strokes (got %d), 0 < t_land (%g s) < "
                "t_final_vent (%g s) < period (%g s), p_stroke > 0 (%g MPa) and, with the "
                "crouch, p_crouch_II2 > 0 (%g MPa)",
                s->nstroke, s->t_land, s->t_final_vent, s->period, s->p_stroke,
                s->p_crouch_II2);
    return NULL;
  }
  csgGait* g = csg_gaitCreate(0, err);
  if (!g) {
    return NULL;
  }
  int ok = 1;
  /* 0 .. period: ACFH take the S-shape, BDEG stand */
  ok = ok && addRow(g, 0, POSE_S, POSE_STRAIGHT, s, err);
  for (int k = 1; k <= s->nstroke && ok; k++) {
    int swing = (k % 2 == 1) ? 0 : 1; /* group whose feet are forward */
    int stand = 1 - swing;
    double t = k * s->period;
    Pose pose[2];
    int last = (k == s->nstroke);
    if (s->crouch) {
      /* the standing group crouches so the forward feet touch down */
      pose[swing] = POSE_S;
      pose[stand] = POSE_Z;
      ok = ok && addRow(g, t, pose[0], pose[1], s, err);
      /* the swinging group lands and vents: its feet drive the support forward */
      pose[swing] = POSE_STRAIGHT;
      pose[stand] = last ? POSE_Z : POSE_S;
      ok = ok && addRow(g, t + s->t_land, pose[0], pose[1], s, err);
      if (last) {
        ok = ok && addRow(g, t + s->t_final_vent, POSE_STRAIGHT, POSE_STRAIGHT, s, err);
      }
    } else {
      /* the paper's table as printed: swap at every whole second, vent all at the end */
      pose[swing] = POSE_STRAIGHT;
      pose[stand] = last ? POSE_STRAIGHT : POSE_S;
      ok = ok && addRow(g, t, pose[0], pose[1], s, err);
    }
  }
  /* end marker: the paper's gait spans nstroke + 1 periods (8 strides in 9 s); a last row
   * equal to the one before it changes nothing and makes the table say how long it lasts */
  if (ok && g->time[g->nrow - 1] < (s->nstroke + 1) * s->period - 1e-9) {
    int r = g->nrow;
    ok = csg_gaitSetRowCount(g, r + 1, err) == CS_OK &&
         csg_gaitSetTime(g, r, (s->nstroke + 1) * s->period, err) == CS_OK;
    for (int lab = 1; ok && lab <= CSG_NLABEL; lab++) {
      csg_gaitSetPressure(g, r, lab, csg_gaitPressure(g, r - 1, lab), NULL);
    }
  }
  if (!ok) {
    csg_gaitDestroy(g);
    return NULL;
  }
  return g;
}
