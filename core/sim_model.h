/* sim_model.h: the co-simulation driver: model (constant during a run) and data (everything a
 * run changes), and the step loop that advances data with a model (MuJoCo's mjModel/mjData).
 *
 * Owns: csOptions (step, end time, output rate, gravity, solver and pneumatic settings, with
 * units and defaults), csModel (options + terrain + gait + robot model + contact law), csData
 * (the ODE world with the support and legs, chamber pressures and their CVODE integrator, time,
 * statistics), and the pipeline:
 *   stage 1 schedule   p_cmd(t) from the gait (gaits_schedule.h), times --pressure-scale
 *   stage 2 pneumatics chamber pressures p follow p_cmd through a first-order lag
 *                      dp/dt = (p_cmd - p)/tau, integrated by CVODE (BDF, diagonal solver)
 *   stage 3 actuation  p -> calibrated segment bends -> leg joint targets (robot_leg.h)
 *   stage 4 contact    robot-terrain contacts, Coulomb friction (contact_ode.h)
 *   stage 5 rigid      ODE steps support and legs by h
 *   stage 6 check      non-finite or runaway state -> CS_ERR_DIVERGED naming the time
 * The support is never driven: it moves only through the legs' contact forces.
 *
 * Ownership: csModel owns its gait (csg_gaitDestroy at cs_modelDestroy); csData owns the ODE
 * world and CVODE memory. cs_dataCreate allocates everything; cs_step allocates nothing. */
#ifndef CS_CORE_SIM_MODEL_H
#define CS_CORE_SIM_MODEL_H

#include <ode/ode.h>

#include "contact_ode.h"
#include "core_status.h"
#include "gaits_csv.h"
#include "gaits_schedule.h"
#include "robot_calibration.h"
#include "robot_robot.h"
#include "terrains_terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csOptions_ {
  double h;               /* fixed macro step (s) */
  double t_end;           /* end time (s); <= 0: the gait's last row time + ramp */
  double output_dt;       /* output sampling interval (s), a multiple of h after rounding */
  double settle;          /* s of unactuated settling under gravity before t = 0 */
  double gravity;         /* mm/s^2 (9.81 m/s^2) */
  int solver_iterations;  /* ODE QuickStep iterations per step */
  double pneumatic_tau;   /* s: chamber pressure lag; 0 = pressures follow p_cmd exactly */
  double pneumatic_rtol;  /* CVODE relative tolerance */
  double pneumatic_atol;  /* CVODE absolute tolerance (MPa) */
  int centerline_points;  /* samples per leg centreline in the output */
  double max_speed;       /* mm/s: a body faster than this means the run diverged */
  int progress;           /* print a progress line to stderr every simulated second */
} csOptions;

/* Defaults with reasons (sim_driver.c). */
csOptions cs_defaultOptions(void);

typedef struct csModel_ {
  csOptions opt;
  cstTerrain terrain;
  csgGait* gait;              /* owned */
  csgScheduleOptions sched;   /* ramp length, pressure scale */
  csrRobotModel robot;
  cscContactParams contact;
  csrCalibration* calibration; /* owned; robot.map points into it */
  char scene[32];
  char gait_path[512];
  char leg_level[16];
} csModel;

/* Fill a model with the defaults of every part (no files read, no map yet). */
void cs_modelInit(csModel* m);

/* Load a scene's files into an initialised model: terrain description, gait table, and the
 * calibration bound to the leg actuator. Options may be changed before and after. On failure
 * err names the file and line. */
csStatus cs_modelLoad(csModel* m, const char* scene, const char* terrain_path,
                      const char* gait_path, const char* calibration_path, csError* err);

/* End time of a run: opt.t_end if > 0, else the gait's last row plus one ramp (s). */
double cs_modelEndTime(const csModel* m);

/* Sway-buckling check of the stance (DESIGN "model no more than a scene needs", a designer's
 * first question): P_cr = π² E I / L² is the critical axial load of one leg clamped at the hip
 * and at a flat foot with the support free to sway (a sway frame of identical columns); the
 * load is the robot's weight shared by half the legs, as in an alternating gait. Both in N. */
void cs_modelStanceCheck(const csModel* m, double mass_total, double* load_per_leg,
                         double* p_critical);

/* Free what the model owns (gait, calibration). NULL-safe. */
void cs_modelDestroy(csModel* m);

typedef struct csData_ csData; /* opaque: ODE world, CVODE memory, state */

/* Build the world for a model: terrain geoms, the robot standing on the terrain at the
 * terrain's start, the pneumatic integrator. Returns NULL with err on failure. */
csData* cs_dataCreate(const csModel* m, csError* err);
void cs_dataDestroy(csData* d);

/* Settle the robot under gravity with all chambers vented for opt.settle seconds (time runs
 * from -settle to 0), then record the support's reference position. */
csStatus cs_settle(const csModel* m, csData* d, csError* err);

/* Advance by one macro step h. On failure returns the status with err naming the time. */
csStatus cs_step(const csModel* m, csData* d, csError* err);

/* Read-outs (valid until the next cs_step). */
double cs_time(const csData* d);
/* support centre displacement from its position at t = 0, world frame, mm */
void cs_supportDisplacement(const csData* d, double pos[3]);
/* support orientation quaternion (w, x, y, z) */
void cs_supportOrientation(const csData* d, double q[4]);
/* actual chamber pressures (96, MPa) */
const double* cs_pressures(const csData* d);
/* centreline of leg k (0..7) at `npts` points, (npts x 3) world mm */
void cs_legCenterline(const csModel* m, const csData* d, int k, int npts, double* out);
/* centre of mass of the robot, world frame, mm */
void cs_robotCenterOfMass(const csModel* m, const csData* d, double com[3]);
/* number of contact points in the last step */
int cs_contactCount(const csData* d);
/* total mass of the robot (t) */
double cs_robotMass(const csData* d);

/* Run from t = 0 to opt.t_end, sampling into an HDF5 file per DESIGN.md's output contract.
 * Writes as it goes and flushes every simulated second, so a run that stops on an error
 * leaves a readable file with the samples so far. `wall_s` gets the wall time of the loop. */
csStatus cs_run(const csModel* m, csData* d, const char* out_path, double* wall_s,
                csError* err);

#ifdef __cplusplus
}
#endif
#endif
