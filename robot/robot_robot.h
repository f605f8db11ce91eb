/* robot_robot.h: the robot assembly: a rigid support with eight legs under it.
 *
 * Owns: csrRobotModel (layout of docs/reference.md "The robot", support mass and size, the leg
 * actuator, leg level and calibration map; constant during a run), csrRobot (the support's ODE
 * body and the eight legs of one instance), the robot's whole state (support body + every
 * leg's state, flat), the support interface of co-simulated legs (hip motion out, base wrench
 * in) and the table of registered leg levels (csr_legTypeFind, robot_leg.h).
 * Legs A, B, C, D form one row and E, F, G, H the other, each row numbered front (+x) to back;
 * A faces E; spacing l_EF along a row, l_AE between rows.
 * World frame: x = crawl direction, y = up, z = lateral. Row A..D is at -z of the centre.
 * The level is stored once: csrRobotModel.leg_type; everything that names the level (the
 * output's leg_model attribute, messages) reads leg_type->name. */
#ifndef CS_ROBOT_ROBOT_H
#define CS_ROBOT_ROBOT_H

#include <ode/ode.h>

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"
#include "robot_odebody.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSR_NLEG 8
#define CSR_NCHAMBER_TOTAL 96

typedef struct csrRobotModel_ {
  csrActuator leg;           /* actuator of every leg */
  csrLegParams leg_params;   /* dynamic leg parameters */
  const csrLegType* leg_type; /* the leg level: the single source of which level runs */
  csrLegSettings leg_settings; /* the level's own settings (for another level than leg_type:
                                 leg_type's defaults, csr_legSettingsRead) */
  char leg_file[512];        /* a level's own file (rom: `crawlsim rom leg-file`); "": none */
  csrBendMap map;            /* calibration: pressure -> segment bend */
  double support_mass;       /* t (1 kg = 1e-3 t) */
  double support_size[3];    /* x length, y thickness, z width of the support box, mm */
  double l_EF;               /* leg spacing along a row, mm */
  double l_AE;               /* spacing between the two rows, mm */
} csrRobotModel;

/* Fill with the documented defaults (actuator `leg`, rod legs, support 210 mm long, 50 g).
 * The map is left empty: the caller supplies the calibration. */
csStatus csr_robotDefaultModel(csrRobotModel* m, csError* err);

/* Hip position of leg k (0..7 = A..H) relative to the support centre's bottom face, mm. */
void csr_robotHipOffset(const csrRobotModel* m, int k, double off[3]);

typedef struct csrRobot_ {
  dBodyID support;
  dGeomID support_geom;
  const csrLegType* type;        /* = the model's leg_type (kept for destroy) */
  csrLeg* legs[CSR_NLEG];
  void* leg_shared;              /* what the legs share (csrLegType.sharedCreate), or NULL */
  double mass_total;             /* t */
  double hip_local[CSR_NLEG][3]; /* hip of leg k from the support's centre, support frame, mm */
  double frame_local[9];         /* the legs' frame (e1, e2, e3 columns) in the support frame */
  int nstate;                    /* doubles of csr_robotStateGet */
  double* scratch;               /* (nstate) internal: the state before a csr_robotStateSet */
} csrRobot;

/* Where the robot is built: the ODE world and space, the step, gravity and the terrain and
 * contact law co-simulated legs use for their own contact. */
typedef struct csrRobotEnv_ {
  dWorldID world;
  dSpaceID space;                  /* robot space: the support's and in-world legs' geoms */
  double h;                        /* ODE step (s) */
  double gravity[3];               /* world mm/s^2 */
  int weightless_legs;             /* 0: `earth`; 1: `paper` (robot_leg.h csrLegSpec) */
  const cstTerrain* terrain;       /* borrowed: must outlive the robot */
  const cscContactParams* contact; /* borrowed: must outlive the robot */
  double heading;                  /* crawl direction at creation: radians about +y,
                                      right-handed, 0 = +x (the terrain's heading) */
} csrRobotEnv;

/* Build the support (centre of its bottom face at `hip_plane_centre`, world mm) turned by
 * env->heading about the vertical, and the eight legs of m->leg_type hanging straight down
 * from it: every leg is created at its turned hip with its frame turned, so a co-simulated
 * leg's own state starts at the heading as the support does. Returns NULL with err on
 * failure. */
csrRobot* csr_robotCreate(const csrRobotModel* m, const csrRobotEnv* env,
                          const double hip_plane_centre[3], csError* err);
void csr_robotDestroy(csrRobot* r);

/* Centre of mass of the whole robot (world, mm). */
void csr_robotCenterOfMass(const csrRobot* r, double com[3]);

/* Apply the 96 chamber pressures (MPa, label order of docs/reference.md) at the start (t0, p0) and
 * end (t1, p1) of the coming macro step to every leg (csrLegType.actuate). Returns 0, or the
 * first leg's non-zero code (> 0 recoverable, < 0 fatal, CSR_MAP_OUT_OF_RANGE). */
int csr_robotActuate(csrRobot* r, double t0, const double p0[CSR_NCHAMBER_TOTAL], double t1,
                     const double p1[CSR_NCHAMBER_TOTAL]);

/* ---- the whole robot state: support body (CSR_BODY_STATE) then leg A..H (stateSize each) */
int csr_robotStateSize(const csrRobot* r);
void csr_robotStateGet(const csrRobot* r, double* x);
/* Bit-exact restore of a state csr_robotStateGet wrote. Returns 0, or -1 if a part refuses
 * its slice of x (non-finite, not a unit quaternion); then the robot is as before the call. */
int csr_robotStateSet(csrRobot* r, const double* x);

/* ---- the support interface of co-simulated legs (robot_leg.h) ----------------------------- */

/* The support body now: centre P (mm), rotation R (row-major 3x3, body axes as columns),
 * velocity of the centre v (mm/s) and angular velocity w (rad/s), world frame. */
void csr_robotSupportPose(const csrRobot* r, double P[3], double R[9], double v[3],
                          double w[3]);

/* Hip motion of leg k for the support at pose (P, R) with twist (v, w) as above. */
void csr_robotBaseStateAt(const csrRobot* r, int k, const double P[3], const double R[9],
                          const double v[3], const double w[3], csrBaseState* b);

/* Hip motion of leg k now, from the support body (world frame; csrBaseState). */
void csr_robotBaseState(const csrRobot* r, int k, csrBaseState* b);

/* Add leg k's base wrench to the support body for the coming ODE step: force w->f at the hip
 * point where it is now, moment w->m (about the hip) as a torque. */
void csr_robotApplyWrench(csrRobot* r, int k, const csrWrench* w);

#ifdef __cplusplus
}
#endif
#endif
