/* robot_robot.h: the robot assembly: a rigid support with eight legs under it.
 *
 * Owns: csrRobotModel (layout of REFERENCE.md "The robot", support mass and size, the leg
 * actuator, leg level and calibration map; constant during a run) and csrRobot (the ODE bodies
 * of one instance). Legs A, B, C, D form one row and E, F, G, H the other, each row numbered
 * front (+x) to back; A faces E; spacing l_EF along a row, l_AE between rows.
 * World frame: x = crawl direction, y = up, z = lateral. Row A..D is at -z of the centre. */
#ifndef CS_ROBOT_ROBOT_H
#define CS_ROBOT_ROBOT_H

#include <ode/ode.h>

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSR_NLEG 8
#define CSR_NCHAMBER_TOTAL 96

typedef struct csrRobotModel_ {
  csrActuator leg;           /* actuator of every leg */
  csrLegParams leg_params;   /* dynamic leg parameters */
  const csrLegType* leg_type;
  csrBendMap map;            /* calibration: pressure -> segment bend */
  double support_mass;       /* t (1 kg = 1e-3 t) */
  double support_size[3];    /* x length, y thickness, z width of the support box, mm */
  double l_EF;               /* leg spacing along a row, mm */
  double l_AE;               /* spacing between the two rows, mm */
} csrRobotModel;

/* Fill with the documented defaults (actuator `leg`, prb legs, support 210 mm long, 50 g).
 * The map is left empty: the caller supplies the calibration. */
csStatus csr_robotDefaultModel(csrRobotModel* m, csError* err);

/* Hip position of leg k (0..7 = A..H) relative to the support centre's bottom face, mm. */
void csr_robotHipOffset(const csrRobotModel* m, int k, double off[3]);

typedef struct csrRobot_ {
  dBodyID support;
  dGeomID support_geom;
  csrLeg* legs[CSR_NLEG];
  double mass_total; /* t */
} csrRobot;

/* Build the support (centre of its bottom face at `hip_plane_centre`, world mm) and the eight
 * legs hanging straight down from it. Returns NULL with err on failure. */
csrRobot* csr_robotCreate(const csrRobotModel* m, dWorldID world, dSpaceID space,
                          const double hip_plane_centre[3], double h, csError* err);
void csr_robotDestroy(const csrRobotModel* m, csrRobot* r);

/* Centre of mass of the whole robot (world, mm). */
void csr_robotCenterOfMass(const csrRobotModel* m, const csrRobot* r, double com[3]);

/* Apply the 96 chamber pressures (MPa, label order of REFERENCE.md) for the coming step.
 * 0 ok, > 0 recoverable, < 0 fatal. */
int csr_robotActuate(const csrRobotModel* m, csrRobot* r, const double p[CSR_NCHAMBER_TOTAL]);

#ifdef __cplusplus
}
#endif
#endif
