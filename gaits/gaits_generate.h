/* gaits_generate.h: gait generators: gait tables built from a few design numbers.
 *
 * Owns: the flat-road gait of the paper (Sec. 5.1): two groups of legs, ACFH and BDEG,
 * alternate; the swinging group holds the S-shape (II1 Ω3&Ω4 and II2 Ω1&Ω2 at p_stroke, foot
 * forward and lifted); at every whole second the swinging group lands and vents, its feet
 * drive the support forward as its legs straighten, and the other group takes the S-shape.
 *
 * The paper's table as printed (crouch = 0, the shipped gaits/flat_road.csv) swaps the groups
 * at every whole second: the venting group lengthens and straightens while the other shortens
 * and bends, both feet sets on the ground for part of the swap. Kinematically (feet that never
 * slip) that cycle moves the support forward and back by the same amount, because the standing
 * group is always the one with the smaller bend; it moves forward in the simulation because
 * friction is load dependent: the lengthening legs take the weight, their feet stick, and the
 * shortening legs' unloaded feet slip forward. A gait that relies less on slip lets the
 * standing group crouch first (crouch = 1, gaits/flat_road_crouch.csv; Z-shape: II1 Ω3&Ω4 and
 * II3 Ω3&Ω4 at p_stroke, II2 Ω1&Ω2 at p_crouch_II2, foot still under the hip, leg shorter than
 * the S-shape) so that the forward feet touch down before anything vents; then the swinging
 * group vents and the standing one changes from the crouch to the S-shape in the air.
 */
#ifndef CS_GAITS_GENERATE_H
#define CS_GAITS_GENERATE_H

#include "core_status.h"
#include "gaits_csv.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csgFlatRoadSpec_ {
  int nstroke;          /* strides (the paper: 8 in 9 s) */
  double period;        /* s per stride */
  double t_land;        /* s into a period when the swinging group lands and vents */
  double t_final_vent;  /* s into the last period when every chamber vents */
  double p_stroke;      /* MPa: S-shape pressure */
  double p_crouch_II2;  /* MPa: II2 pressure of the crouch */
  int crouch;           /* 1: with the crouch; 0: the paper's table as printed */
} csgFlatRoadSpec;

/* nstroke 8, period 1 s, t_land 0.35 s, t_final_vent 0.8 s, crouch off (the paper's table);
 * pressures 0 (the
 * caller derives them from the leg model, robot_gaitdesign.h). */
csgFlatRoadSpec csg_defaultFlatRoadSpec(void);

/* Build the table. Returns NULL with err for an invalid spec. */
csgGait* csg_generateFlatRoad(const csgFlatRoadSpec* spec, csError* err);

#ifdef __cplusplus
}
#endif
#endif
