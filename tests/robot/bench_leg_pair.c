/* bench_leg_pair.c: one leg of each level (rod, strain) under the same hip boundary conditions, on
 * the flat road (not a test: prints them side by side every 0.1 s).
 *
 *   bench_leg_pair swing|side|push [support_g] [side_speed_mm_s] [t_end_s] [LEVEL[:N] ...]
 *
 * LEVEL[:N]: up to 4 levels with N links / elements / bending modes per segment (default rod
 * and strain at their defaults); the calibration is $CS_CALIBRATION if set (a path from the
 * source directory, e.g. robot/calibration_fe_leg.h5, the pair-mode table), else the mission's
 * table, robot/calibration_fe_leg_modes_sym.h5 (its own rule).
 *
 * The leg is weightless (conditions `paper`); the flat-road gait's S-shape (II1 Ω3&Ω4 and II2
 * Ω1&Ω2 at 0.1744 MPa, smoothstep ramps of 0.2 s) where a case actuates.
 *  - swing: the hip clamped 500 mm up, nothing touches: the S-shape at t = 0, vented at 1 s: the
 *    foot's whip (the legs' dynamics alone).
 *  - side: a stance foot loaded sideways: the hip carries a support of support_g grams (12.5:
 *    a quarter of the 50 g support, one of four stance legs under `paper`) free to move
 *    vertically only, under 9.81 m/s^2, so the normal load is its weight; from t = 0 the hip
 *    moves along x at side_speed (5 mm/s) while the foot is held by friction: the lateral force
 *    and the foot's drift (sole tilt plus any slip).
 *  - push: one leg pushing a fixed support: the same vertically free support, its x held; the
 *    S-shape at t = 0 (the bending leg pushes the support back through its foot), vented at
 *    1 s.
 * An in-world level (none is registered since prb was retired): its ODE bodies with the
 * support body on a slider to a kinematic carriage (x prescribed, y free), QuickStep at 1 ms
 * with 240 iterations, ODE contacts. rod, strain: the hip's vertical degree
 * of freedom integrated here at H = 1 ms, implicitly in the leg's condensed vertical gain (the
 * driver's stabilised scheme in one dimension: (M + H A) v' = M v + H (W - M g) + H A v). The
 * data files come from $CS_SOURCE_DIR (default ../../..). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_ode.h"
#include "robot_calibration.h"
#include "robot_leg.h"
#include "robot_rod.h"
#include "terrains_terrain.h"

enum { NCL = 25, MAX_LEVELS = 4 };
static const double kP = 0.1744; /* MPa: the flat-road gait's S-shape */

typedef struct {
  const csrLegType* T;
  csrLeg* leg;
  dWorldID world;
  dSpaceID terrain_space, robot_space;
  dJointGroupID contacts;
  dBodyID support, carriage;
  dJointID slider;
  dJointFeedback fb;
  double M;       /* support mass (t) */
  double hip0[3]; /* the hip at creation */
  double y, vy;   /* rod: the hip's height and vertical speed */
  double Fx;      /* the leg's horizontal force on the support (N) */
} Rig;


static double smooth(double u) {
  u = u < 0 ? 0 : (u > 1 ? 1 : u);
  return u * u * (3 - 2 * u);
}


/* the S-shape's pressures at t: on from t_on, off from t_off (0.2 s ramps) */
static void gaitPressures(double t, double t_on, double t_off, double p[12]) {
  memset(p, 0, 12 * sizeof(double));
  double level = kP * (smooth((t - t_on) / 0.2) - smooth((t - t_off) / 0.2));
  p[2] = p[3] = p[4] = p[5] = level;
}


/* the hip's x at t and its speed (side: at rest until 0, then v after a 0.1 s ramp) */
static void hipX(double t, double v, double x0, double* x, double* vx) {
  const double r = 0.1;
  *x = x0 + v * (t <= 0 ? 0 : (t < r ? t * t / (2 * r) : t - r / 2));
  *vx = v * (t <= 0 ? 0 : fmin(1, t / r));
}


/* links: the level's setting links (0: its default) */
static int rigCreate(Rig* r, const char* level, int links, int clamp_high, double M,
                     csrActuator* act, csrLegParams* lp, const csrBendMap* map,
                     const cstTerrain* tr, const cscContactParams* cp) {
  memset(r, 0, sizeof *r);
  csError err;
  cs_errorClear(&err);
  r->T = csr_legTypeFind(level, NULL);
  if (!r->T) {
    return 1;
  }
  r->M = M;
  r->hip0[0] = 300;
  r->hip0[1] = clamp_high ? 500 : csr_actuatorLength(act) + 0.3;
  r->hip0[2] = 150;
  r->y = r->hip0[1];
  r->world = dWorldCreate();
  dWorldSetGravity(r->world, 0, -9810, 0);
  dWorldSetQuickStepNumIterations(r->world, 240);
  r->terrain_space = dSimpleSpaceCreate(0);
  r->robot_space = dSimpleSpaceCreate(0);
  r->contacts = dJointGroupCreate(0);
  cst_terrainBuildOde(tr, r->terrain_space);
  /* the support: the robot's box, M; on a vertical slider to a kinematic carriage */
  r->support = dBodyCreate(r->world);
  r->carriage = dBodyCreate(r->world);
  dMass ms;
  dMassSetBoxTotal(&ms, M, 210, 10, 145);
  dBodySetMass(r->support, &ms);
  dBodySetPosition(r->support, r->hip0[0], r->hip0[1], r->hip0[2]);
  dBodySetPosition(r->carriage, r->hip0[0], r->hip0[1], r->hip0[2]);
  dBodySetKinematic(r->carriage);
  r->slider = dJointCreateSlider(r->world, 0);
  dJointAttach(r->slider, r->support, r->carriage);
  dJointSetSliderAxis(r->slider, 0, 1, 0);
  dJointSetFeedback(r->slider, &r->fb);
  if (clamp_high) {
    dBodySetKinematic(r->support);
  }
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  csrLegSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = act;
  sp.params = lp;
  csrLegSettings set;
  csr_legSettingsDefault(r->T, &set);
  if (links > 0 && csr_legSettingSet(r->T, &set, "links", links, &err) != CS_OK) {
    fprintf(stderr, "bench_leg_pair: %s\n", err.msg);
    return 1;
  }
  sp.settings = &set;
  sp.map = map;
  memcpy(sp.hip, r->hip0, sizeof sp.hip);
  memcpy(sp.frame, F, sizeof F);
  sp.h = 1e-3;
  sp.gravity[1] = -9810;
  sp.weightless = 1;
  sp.world = r->world;
  sp.space = r->robot_space;
  sp.support = r->support;
  sp.terrain = tr;
  sp.contact = cp;
  r->leg = r->T->create(&sp, &err);
  if (!r->leg) {
    fprintf(stderr, "bench_leg_pair: %s\n", err.msg);
    return 1;
  }
  return 0;
}


static void rigDestroy(Rig* r) {
  if (r->leg) {
    r->T->destroy(r->leg);
  }
  if (r->world) {
    dJointGroupDestroy(r->contacts);
    dSpaceDestroy(r->robot_space);
    dSpaceDestroy(r->terrain_space);
    dWorldDestroy(r->world);
  }
}


/* one 1 ms step from t; hip x prescribed by (x1, vx0 -> vx1), y free unless clamped */
static int rigStep(Rig* r, double t, int clamped, double x0, double x1, double vx0, double vx1,
                   const double p0[12], const double p1[12], const cscContactParams* cp) {
  const double H = 1e-3;
  csError err;
  cs_errorClear(&err);
  int rc = r->T->actuate(r->leg, t, p0, t + H, p1);
  if (rc != 0) {
    return rc;
  }
  if (r->T->in_world) {
    dBodySetPosition(r->carriage, x1, r->hip0[1], r->hip0[2]);
    dBodySetLinearVel(r->carriage, vx1, 0, 0);
    cscContactStats st;
    csc_collide(cp, r->world, r->terrain_space, r->robot_space, r->contacts, H, &st);
    dWorldQuickStep(r->world, H);
    dJointGroupEmpty(r->contacts);
    r->y = dBodyGetPosition(r->support)[1];
    /* the slider holds x: its force on the support balances the leg's */
    r->Fx = -r->fb.f1[0];
    return 0;
  }
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  csrBaseState b0, b1;
  memset(&b0, 0, sizeof b0);
  memcpy(b0.R, F, sizeof F);
  b1 = b0;
  b0.x[0] = x0;
  b0.x[1] = r->y;
  b0.x[2] = r->hip0[2];
  b0.v[0] = vx0;
  b0.v[1] = clamped ? 0 : r->vy;
  b1.x[0] = x1;
  b1.x[1] = r->y + (clamped ? 0 : H * r->vy);
  b1.x[2] = r->hip0[2];
  b1.v[0] = vx1;
  b1.v[1] = b0.v[1];
  csrWrench w;
  rc = r->T->advance(r->leg, t, H, &b0, &b1, &w, &err);
  if (rc != 0) {
    fprintf(stderr, "bench_leg_pair: %s\n", err.msg);
    return rc;
  }
  if (!clamped) {
    double K[36], C[36];
    r->T->interfaceGains(r->leg, K, C);
    double A = H * K[7] + C[7];
    double vn = (r->M * r->vy + H * (w.f[1] - r->M * 9810) + H * A * r->vy) / (r->M + H * A);
    r->y += H * vn;
    r->vy = vn;
  }
  r->Fx = w.f[0];
  return 0;
}


int main(int argc, char** argv) {
  const char* scen = argc > 1 ? argv[1] : "side";
  double M = (argc > 2 ? atof(argv[2]) : 12.5) * 1e-6; /* g -> t */
  double vside = argc > 3 ? atof(argv[3]) : 5.0;
  double t_end = argc > 4 ? atof(argv[4]) : 3.0;
  const int swing = !strcmp(scen, "swing"), side = !strcmp(scen, "side"),
            push = !strcmp(scen, "push");
  if (!swing && !side && !push) {
    fprintf(stderr, "usage: bench_leg_pair swing|side|push [support_g] [side_speed] [t_end]\n");
    return 1;
  }
  const char* src = getenv("CS_SOURCE_DIR");
  char cal_path[600], terr_path[600];
  const char* cal_rel = getenv("CS_CALIBRATION");
  snprintf(cal_path, sizeof cal_path, "%s/%s", src ? src : "../../..",
           cal_rel ? cal_rel : "robot/calibration_fe_leg_modes_sym.h5");
  snprintf(terr_path, sizeof terr_path, "%s/terrains/flat_road.terrain", src ? src : "../../..");
  dInitODE2(0);
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  csr_actuatorPreset(&act, "leg", &err);
  csrCalibration* cal = csr_calibrationOpen(cal_path, &act, &err);
  cstTerrain tr;
  if (!cal || cst_terrainLoad(&tr, terr_path, &err) != CS_OK) {
    fprintf(stderr, "bench_leg_pair: %s\n", err.msg);
    return 1;
  }
  csrBendMap map = csr_calibrationMap(cal);
  cscContactParams cp = csc_defaultContactParams();
  Rig rig[MAX_LEVELS];
  char names[MAX_LEVELS][32];
  csrLegParams lp[MAX_LEVELS];
  int nlev = 0;
  for (int a = 5; a < argc && nlev < MAX_LEVELS; a++, nlev++) {
    snprintf(names[nlev], sizeof names[nlev], "%s", argv[a]);
  }
  if (nlev == 0) {
    snprintf(names[0], sizeof names[0], "rod");
    snprintf(names[1], sizeof names[1], "strain");
    nlev = 2;
  }
  for (int i = 0; i < nlev; i++) {
    char level[32];
    snprintf(level, sizeof level, "%s", names[i]);
    char* colon = strchr(level, ':');
    lp[i] = csr_defaultLegParams(&act);
    int links = 0;
    if (colon) {
      *colon = 0;
      links = atoi(colon + 1);
    }
    if (rigCreate(&rig[i], level, links, swing, M, &act, &lp[i], &map, &tr, &cp) != 0) {
      fprintf(stderr, "bench_leg_pair: level %s not created\n", names[i]);
      return 1;
    }
    /* the leg's mass and its first moment about the hip at creation (the levels' inertia) */
    double mx[3];
    rig[i].T->massMoment(rig[i].leg, mx);
    const double ml = rig[i].T->mass(rig[i].leg);
    printf("%s: mass %.6g g, centre of mass from the hip %.4f %.4f %.4f mm\n", names[i],
           ml * 1e6, mx[0] / ml - rig[i].hip0[0], mx[1] / ml - rig[i].hip0[1],
           mx[2] / ml - rig[i].hip0[2]);
  }
  const double t_on = (swing || push) ? 0 : 1e9, t_off = (swing || push) ? 1 : 1e9;
  double foot0[MAX_LEVELS] = {NAN, NAN, NAN, NAN};
  printf("%s: support %.1f g; per level: hip y (mm from start), Fx on the support (N), foot x "
         "from the hip's start, foot height, foot drift since t = 0 (mm), contact depth (mm), "
         "contact force x, y (N)\n", scen, M * 1e6);
  for (long k = 0; k * 1e-3 < t_end + 0.5 - 1e-9; k++) {
    double t = -0.5 + k * 1e-3, x0, x1, v0, v1, p0[12], p1[12];
    hipX(t, side ? vside : 0, rig[0].hip0[0], &x0, &v0);
    hipX(t + 1e-3, side ? vside : 0, rig[0].hip0[0], &x1, &v1);
    gaitPressures(t, t_on, t_off, p0);
    gaitPressures(t + 1e-3, t_on, t_off, p1);
    for (int i = 0; i < nlev; i++) {
      if (rigStep(&rig[i], t, swing, x0, x1, v0, v1, p0, p1, &cp) != 0) {
        return 1;
      }
    }
    double tn = t + 1e-3;
    if (tn > -1e-9 && fabs(tn * 10 - round(tn * 10)) < 1e-6) {
      printf("t %5.2f", tn);
      for (int i = 0; i < nlev; i++) {
        double cl[3 * NCL];
        rig[i].T->centerline(rig[i].leg, NCL, cl);
        const double* foot = cl + 3 * (NCL - 1);
        if (isnan(foot0[i])) {
          foot0[i] = foot[0];
        }
        double fc[3] = {NAN, NAN, NAN};
        double depth = rig[i].T->contactDepth ? rig[i].T->contactDepth(rig[i].leg) : NAN;
        if (rig[i].T->contactForce) {
          rig[i].T->contactForce(rig[i].leg, fc);
        }
        printf(" | %s y %7.3f Fx %+7.4f foot %7.3f h %6.3f drift %+7.3f depth %6.3f Fc %+7.4f "
               "%+7.4f", names[i], rig[i].y - rig[i].hip0[1], rig[i].Fx, foot[0] - rig[i].hip0[0],
               foot[1], foot[0] - foot0[i], depth, fc[0], fc[1]);
      }
      printf("\n");
    }
  }
  /* the foot's box at the end (contactShapes' last shape, when the level draws one): its
   * lowest corner and the tilt of its axis 3 from the vertical, against the tip node */
  for (int i = 0; i < nlev; i++) {
    csrContactShape sh[256];
    int ns = rig[i].T->contactShapes ? rig[i].T->contactShapes(rig[i].leg, sh, 256) : 0;
    if (ns > 0 && sh[ns - 1].kind == CSR_SHAPE_BOX) {
      const csrContactShape* b = &sh[ns - 1];
      double low = INFINITY;
      for (int c = 0; c < 8; c++) {
        double y = b->a[1];
        for (int ax = 0; ax < 3; ax++) {
          y += ((c >> ax) & 1 ? 1 : -1) * b->half[ax] * b->R[3 + ax];
        }
        low = fmin(low, y);
      }
      printf("%s: foot box centre y %.3f, lowest corner y %.3f mm, half %.2f %.2f %.2f, axis 3 "
             "vertical component %.4f\n", names[i], b->a[1], low, b->half[0], b->half[1],
             b->half[2], b->R[5]);
    }
  }
  for (int i = 0; i < nlev; i++) {
    rigDestroy(&rig[i]);
  }
  csr_calibrationClose(cal);
  dCloseODE();
  return 0;
}
