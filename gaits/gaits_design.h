/* gaits_design.h: gait design descriptions: a short text that says which legs take which
 * shape when and how fast; robot_gaitdesign.h turns it into a gait table with pressures from
 * the calibrated leg model (`crawlsim gait design`).
 *
 * Owns: csgDesign (poses, moves; the model of a description, constant once read) and its
 * reader with "<file>:<line>: <cause>" errors. Depends on nothing of ours but the leaf helpers.
 *
 * Format (one statement per line, '#' starts a comment, units s, mm, deg, MPa; leg frame of
 * docs/reference.md: e1 = crawl direction +x, e2 = lateral +z, e3 down the leg):
 *   name WORD                          the gait's name
 *   sample S                           s between the table's rows inside a move (default 0.05)
 *   ramp R                             the actuation time (s) the design assumes: the table
 *                                      states it as its ramp (`# @ramp R`, gaits_schedule.h),
 *                                      which a run uses where --ramp is not given (default: the
 *                                      sample, so each row's change fills the interval to the
 *                                      next and the run plays the designed motion)
 *   pose NAME SETS... TARGET VALUE     add a chamber set to pose NAME (poses are built from
 *                                      their set lines in file order; `straight` = all vented
 *                                      is built in). SETS: one or more II<s>:<chambers>, e.g.
 *                                      II1:3,4 II2:1,2: one common pressure on those chambers.
 *                                      TARGET says what that pressure must achieve, given the
 *                                      pose's earlier sets:
 *                                        stroke MM   foot offset along e1 (from the straight leg)
 *                                        side MM     foot offset along e2
 *                                        lift MM     foot raised towards the hip (leg shorter)
 *                                        rise MM     foot lowered away from the hip (longer: an
 *                                                    elongation mode)
 *                                        bend DEG    bend of the set's first segment
 *                                        pressure P  this pressure (MPa)
 *                                        pressure-of POSE  the pressure POSE gives these
 *                                                    chambers (its set sharing one of them,
 *                                                    else its first set)
 *   pose NAME foot X LIFT [plus|minus] a whole pose in the leg's sagittal plane: the foot at X
 *                                      mm along e1 and LIFT mm above the straight leg's foot,
 *                                      its sole level (the bends of II1, II2, II3 sum to zero);
 *                                      each segment bends with Ω3&Ω4 (towards +e1) or Ω1&Ω2.
 *                                      Two level-sole shapes reach most (X, LIFT): without a
 *                                      word the solver takes II1 on Ω3&Ω4 for X > 0 and on
 *                                      Ω1&Ω2 for X < 0; `plus` / `minus` name II1's pair. A
 *                                      move between two foot poses of the same named branch
 *                                      stays on it (no pass through a straight leg at X = 0)
 *   move T0 DURATION LEGS POSE [linear|ease-in|ease-out]
 *                                      legs LEGS (letters A..H, e.g. ACFH) go from the pose
 *                                      they hold to POSE, starting at T0, taking DURATION s
 *                                      (0: one row at T0, the run's ramp makes the change);
 *                                      `linear`: at constant speed instead of the smoothstep;
 *                                      `ease-in`: from rest, speeding up evenly (s = u^2),
 *                                      `ease-out`: the reverse (to rest)
 *   stride N PERIOD T0 LEGS1 LEGS2     N strides of PERIOD s from T0. In stride k (0-based) the
 *                                      `swing` legs are LEGS1 for even k, LEGS2 for odd k (the
 *                                      legs whose feet are forward when the stride starts), the
 *                                      `stand` legs the other set. Its phases follow:
 *   phase START DURATION ROLE POSE [last POSE2] [linear|ease-in|ease-out]
 *                                      in every stride, the ROLE (swing | stand) legs move to
 *                                      POSE at START s into the stride (POSE2 in the last one)
 *   foothold T LEGS OFFSETS [margin MM]
 *                                      the step of LEGS lifting at T (s) is a foothold: its
 *                                      landing is chosen during the run among the OFFSETS
 *                                      (mm ahead of the hip, comma-separated) from where the
 *                                      support stands, keeping MM (default 10) from the
 *                                      terrain's edges (gaits_foothold.h). The table written
 *                                      holds the plan's candidate; the candidates' tables and
 *                                      the companion NAME.foothold come from the generator that
 *                                      knows each offset's moves (tools/obstacle_gait.py
 *                                      --foothold-out): this reader records and checks the line
 *   end T                              the table ends with a row at T (s) repeating the last
 *   mirror LEGS                        legs LEGS take every pose reflected across their own
 *                                      sagittal plane (e2 -> -e2: chambers Ω1<->Ω2, Ω3<->Ω4):
 *                                      a sideways bend then points the other way, so a group's
 *                                      lateral reactions can cancel in force and in yaw moment
 * A leg's moves may not overlap in time. Inside a move the legs follow the pressure path from
 * the old pose's pressures to the new pose's, timed so that the foot moves along its path with
 * the smoothstep profile 3u^2 - 2u^3 of u = (t - T0)/DURATION (robot_gaitdesign.h). */
#ifndef CS_GAITS_DESIGN_H
#define CS_GAITS_DESIGN_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 128: the obstacle gait's walk coming down past the step takes a pose family per stretch
 * (tools/obstacle_gait.py rule 10: 98 poses) */
#define CSG_DESIGN_MAX_POSES 128
#define CSG_DESIGN_MAX_SETS 6
#define CSG_DESIGN_MAX_MOVES 1024
#define CSG_DESIGN_NAME 32
#define CSG_DESIGN_MAX_FOOTHOLDS 16 /* gaits_foothold.h CSG_FOOTHOLD_MAX */
#define CSG_DESIGN_MAX_OFFSETS 12   /* gaits_foothold.h CSG_FOOTHOLD_MAX_CAND */
/* pose index of the built-in all-vented pose */
#define CSG_POSE_STRAIGHT 0

typedef enum csgTargetKind_ {
  CSG_TARGET_PRESSURE = 0,    /* value = MPa */
  CSG_TARGET_PRESSURE_OF = 1, /* ref = pose whose first set's pressure is used */
  CSG_TARGET_STROKE = 2,      /* value = mm along e1 */
  CSG_TARGET_SIDE = 3,        /* value = mm along e2 */
  CSG_TARGET_LIFT = 4,        /* value = mm towards the hip */
  CSG_TARGET_RISE = 5,        /* value = mm away from the hip */
  CSG_TARGET_BEND = 6,        /* value = deg of the set's first segment */
  CSG_TARGET_FOOT = 7         /* value = foot offset along e1 (mm), value2 = lift (mm): the
                                 whole leg in its sagittal plane (see `pose NAME foot`) */
} csgTargetKind;

/* One chamber set of a pose: a common pressure on chambers[] and what it must achieve. */
typedef struct csgDesignSet_ {
  unsigned char chambers[12]; /* 1: chamber 4 s + j (segment s 0..2, chamber j 0..3) is in */
  csgTargetKind kind;
  double value;
  double value2;              /* CSG_TARGET_FOOT: lift (mm) */
  int branch;                 /* CSG_TARGET_FOOT: 0 the solver's choice (Ω3&Ω4 on II1 for X > 0,
                                 Ω1&Ω2 for X < 0); +1 `plus`: II1 bends towards +e1 (Ω3&Ω4),
                                 -1 `minus`: towards -e1 (Ω1&Ω2), whatever the sign of X */
  int ref;                    /* pose index for CSG_TARGET_PRESSURE_OF */
  int line;                   /* where it was given */
} csgDesignSet;

typedef struct csgDesignPose_ {
  char name[CSG_DESIGN_NAME];
  int nset;
  csgDesignSet set[CSG_DESIGN_MAX_SETS];
  int line;                   /* first line of the pose */
} csgDesignPose;

enum { CSG_PROFILE_SMOOTH = 0, CSG_PROFILE_LINEAR = 1, CSG_PROFILE_EASE_IN = 2,
       CSG_PROFILE_EASE_OUT = 3 };

typedef struct csgDesignMove_ {
  double t0, duration;        /* s */
  unsigned legs;              /* bit k: leg k (0..7 = A..H) */
  int pose;                   /* target pose index */
  int linear;                 /* the time profile s(u) along the path, u = (t - t0)/duration:
                                 CSG_PROFILE_SMOOTH 3u^2 - 2u^3 (starts and ends at rest),
                                 CSG_PROFILE_LINEAR u (constant speed: a conveyor whose
                                 successive moves join without a stop), CSG_PROFILE_EASE_IN u^2
                                 (from rest to the linear speed x 2 at the end),
                                 CSG_PROFILE_EASE_OUT 2u - u^2 (the reverse) */
  int line;                   /* the move or phase line it came from */
} csgDesignMove;

/* a `foothold` line */
typedef struct csgDesignFoothold_ {
  double t;                   /* s: the lift */
  unsigned legs;
  int noffset;
  double offset[CSG_DESIGN_MAX_OFFSETS]; /* mm ahead of the hip */
  double margin;              /* mm */
  int line;
} csgDesignFoothold;

typedef struct csgDesign_ {
  char name[64];
  char source[256];
  double sample;              /* s */
  double ramp;                /* s; 0: not stated (the table states the sample) */
  double end;                 /* s; 0: no end row */
  unsigned mirror;            /* legs (bit k = leg k) that use the poses reflected (e2 -> -e2) */
  int npose;                  /* pose[0] is `straight` */
  csgDesignPose pose[CSG_DESIGN_MAX_POSES];
  int nstride;                /* stride statements read */
  double stride_t0, stride_period; /* s: the first stride's start and period */
  int stride_n;               /* its number of strides */
  int nmove;                  /* sorted by t0 (stable), strides expanded */
  csgDesignMove move[CSG_DESIGN_MAX_MOVES];
  int nfoothold;              /* `foothold` lines, in file order */
  csgDesignFoothold foothold[CSG_DESIGN_MAX_FOOTHOLDS];
} csgDesign;

/* Read a description (format above) into *d (caller memory; it is large, ~76 KB: allocate it).
 * Errors "<file>:<line>: <cause>" (CS_ERR_PARSE malformed, CS_ERR_RANGE values; CS_ERR_IO
 * "<file>: cannot open ..."). Checks: known statements and word counts, finite numbers,
 * names, legs A..H, chamber sets, targets, poses defined before use (pressure-of: a pose with
 * at least one set), phases after a stride, overlapping moves of one leg, end after the last
 * move. */
csStatus csg_designRead(csgDesign* d, const char* path, csError* err);

/* Index of the pose called `name`, or -1. */
int csg_designPoseFind(const csgDesign* d, const char* name);

/* "ACFH" for a leg mask (buf of at least 9 bytes). */
void csg_designLegsFormat(unsigned legs, char* buf);

#ifdef __cplusplus
}
#endif
#endif
