/* robot_leg.h: the one leg interface every dynamic leg level implements (prb now; rod and rom
 * later), and the pressure -> segment-bend map (the calibration) the levels share.
 *
 * Owns: csrBendMap (pressures of one segment's four chambers -> bend vector of that segment),
 * csrLegSpec (everything a leg needs to build itself in the ODE world), and csrLegType, a const
 * table of operations (STYLE.md 11; SUNDIALS/MuJoCo-plugin style). A leg's state lives in ODE
 * bodies (prb) or in its own arrays; the driver only calls the table.
 *
 * Frames: a leg's frame (e1, e2, e3) is given in world coordinates; e3 runs from the hip
 * (base of II1) to the foot along the undeformed leg; e1, e2 span the cross-section with the
 * chamber layout of REFERENCE.md (Ω1 = (+b,+b), Ω2 = (+b,-b), Ω3 = (-b,-b), Ω4 = (-b,+b)). */
#ifndef CS_ROBOT_LEG_H
#define CS_ROBOT_LEG_H

#include <ode/ode.h>

#include "core_status.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The calibration: pressures p[4] (MPa) of segment `seg` (0..2) -> bend vector bend[2] (rad):
 * the segment's end tangent turns by |bend| towards the cross-section direction
 * (bend[0] e1 + bend[1] e2)/|bend|; and the axial stretch of the segment's centreline (-).
 * Returns 0 on success, > 0 recoverable, < 0 fatal (as SUNDIALS right-hand sides do). */
typedef int (*csrBendMapFn)(const void* ctx, int seg, const double p[4], double bend[2],
                            double* stretch);

typedef struct csrBendMap_ {
  csrBendMapFn eval;
  const void* ctx;   /* owned by whoever built the map; must outlive the legs */
  const char* name;  /* e.g. "analytic x scale (provisional)" */
  double p_max;      /* MPa: highest chamber pressure the map is calibrated for (INFINITY: any) */
} csrBendMap;

/* eval's return for a pressure above csrBendMap.p_max (fatal: the run must not extrapolate) */
#define CSR_MAP_OUT_OF_RANGE (-2)

/* Parameters of the dynamic leg levels (model side; defaults in robot_prb.c). */
typedef struct csrLegParams_ {
  int links_per_segment;  /* prb: rigid links per segment (joint length S/n) */
  double E_bend;          /* effective bending modulus of the silicone section (MPa) */
  double damping_time;    /* material damping as a time constant: kd = k * damping_time (s) */
  double contact_radius;  /* radius of the leg's collision capsules (mm) */
} csrLegParams;

/* Everything a leg needs to build itself. */
typedef struct csrLegSpec_ {
  const csrActuator* act;
  const csrLegParams* params;
  const csrBendMap* map;
  dWorldID world;
  dSpaceID space;       /* robot space: the leg's collision geoms go here */
  dBodyID support;      /* body the leg's base (hip) is clamped to */
  double hip[3];        /* hip position, world, mm */
  double frame[9];      /* columns e1, e2, e3 in world coordinates (row-major 3x3) */
  double h;             /* fixed step (s): the joint springs are mapped to ERP/CFM with it */
  double gravity;       /* mm/s^2, used only to report static sag */
} csrLegSpec;

typedef struct csrLeg_ csrLeg; /* opaque, per level */

typedef struct csrLegType_ {
  const char* name;
  /* build the leg in spec->world; returns NULL and fills err on failure */
  csrLeg* (*create)(const csrLegSpec* spec, csError* err);
  void (*destroy)(csrLeg* leg);
  /* set the actuation for the coming step from the 12 chamber pressures p[3][4] (MPa);
   * 0 ok, > 0 recoverable, < 0 fatal */
  int (*actuate)(csrLeg* leg, const double p[12]);
  /* sample the centreline from hip to foot at k points (world, mm), out is (k x 3) */
  void (*centerline)(const csrLeg* leg, int k, double* out);
  /* total mass of the leg (t) */
  double (*mass)(const csrLeg* leg);
  /* first mass moment: sum of m_i x_i over the leg's bodies (t mm, world) */
  void (*massMoment)(const csrLeg* leg, double mx[3]);
} csrLegType;

/* The pseudo-rigid-body chain level (robot_prb.c). */
extern const csrLegType csr_leg_prb;

/* Second moment of area of the chambered section about a principal axis (mm^4). */
double csr_legSectionI(const csrActuator* act);

/* Default leg parameters for an actuator (E_bend from C10, see robot_prb.c). */
csrLegParams csr_defaultLegParams(const csrActuator* act);

#ifdef __cplusplus
}
#endif
#endif
