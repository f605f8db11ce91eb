/* robot_actuator.h: the 3D-FRSPA actuator description (geometry, material, fibres).
 *
 * Owns: csrActuator, the named geometries of docs/reference.md (`fig1`, `baseline`, `leg`), setting
 * any parameter by its paper name (S1 S2 S3 n1 n2 n3 LS12 LS23 a b c r1 r2 C10 C20, plus rho,
 * Ef, nuf, rhof, rf), validation of a parameter set, and the bend-curve record that every model
 * level (analytic, rod, rom, fe) fills for `crawlsim bend`.
 *
 * Units: mm, MPa (N/mm^2), t/mm^3 (so that mm-N-s is consistent), turns are counts.
 * Frames: a segment's cross-section frame (e1, e2), axis e3 from base to tip; chamber centres
 * Ω1 = (+b,+b), Ω2 = (+b,-b), Ω3 = (-b,-b), Ω4 = (-b,+b) (docs/reference.md convention). */
#ifndef CS_ROBOT_ACTUATOR_H
#define CS_ROBOT_ACTUATOR_H

#include <stddef.h>

#include "core_math.h"
#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSR_NSEG 3     /* segments II1..II3 per actuator */
#define CSR_NCHAMBER 4 /* chambers Ω1..Ω4 per segment */

typedef struct csrActuator_ {
  char name[32];         /* preset it started from ("baseline", ...) */
  double S[CSR_NSEG];    /* segment lengths S1..S3 (mm) */
  double n[CSR_NSEG];    /* fibre turns per segment n1..n3 (count, 0 = no fibre) */
  double LS[CSR_NSEG - 1]; /* solid joint lengths LS12, LS23 (mm) */
  double a;              /* half side of the square cross-section (mm) */
  double b;              /* chamber centre offset from the axis, per direction (mm) */
  double c;              /* solid end cap between a chamber and its segment's end face (mm) */
  double r1;             /* chamber radius (mm) */
  double r2;             /* outer corner fillet radius (mm) */
  double C10, C20;       /* Yeoh constants of Elastosil M4601 (MPa) */
  double rho;            /* silicone density (t/mm^3) */
  double Ef, nuf, rhof;  /* Kevlar fibre Young's modulus (MPa), Poisson ratio, density (t/mm^3) */
  double rf;             /* fibre section radius (mm) */
} csrActuator;

/* Fill `act` with a named preset ("fig1", "baseline", "leg"). CS_ERR_ARG for an unknown name. */
csStatus csr_actuatorPreset(csrActuator* act, const char* name, csError* err);

/* Set one parameter by its paper name, e.g. ("r1", 2.5). Unknown names -> CS_ERR_ARG. */
csStatus csr_actuatorSet(csrActuator* act, const char* pname, double value, csError* err);

/* Parse "NAME=VALUE" (the --set flag) and apply it. */
csStatus csr_actuatorSetString(csrActuator* act, const char* assignment, csError* err);

/* Check geometric and material consistency (positive sizes, chamber inside the wall, caps
 * shorter than half a segment, fillet smaller than the half side, C10 > 0, ...). */
csStatus csr_actuatorValidate(const csrActuator* act, csError* err);

/* The paper's single-segment model (its Sec. 3.3 and Table 1: part II1 of the Fig. 1a actuator
 * analysed alone): `one` = `act` with S2 = S3 = LS12 = LS23 = 0 and n2 = n3 = 0, so that every
 * length, start and volume below describes segment II1 alone. Only the FE meshes it
 * (csr_actuatorValidateSingle); the other model levels take three segments
 * (csr_actuatorValidate refuses S2 = 0). */
void csr_actuatorSingleSegment(const csrActuator* act, csrActuator* one);

/* 1 when `act` is a single-segment actuator (S2 = S3 = LS12 = LS23 = 0), else 0. */
int csr_actuatorIsSingle(const csrActuator* act);

/* Validate either form: three segments (csr_actuatorValidate) or a single segment (II1 as
 * csr_actuatorValidate checks it, n2 = n3 = 0). For the FE, the only level that meshes one. */
csStatus csr_actuatorValidateSingle(const csrActuator* act, csError* err);

/* Total length S1 + LS12 + S2 + LS23 + S3 (mm). */
double csr_actuatorLength(const csrActuator* act);

/* Arc-length start of segment s (0-based) from the base (mm). */
double csr_actuatorSegmentStart(const csrActuator* act, int s);

/* Solid cross-section area of the outer square with fillets (mm^2), chambers not removed. */
double csr_actuatorOuterArea(const csrActuator* act);

/* Names of the parameters csr_actuatorSet accepts, NULL-terminated (for --help and tests). */
extern const char* const csr_actuator_param_names[];

/* Write the actuator parameters as attributes is done by the caller through this visitor. */
typedef void (*csrParamVisitor)(void* user, const char* name, double value);
void csr_actuatorVisit(const csrActuator* act, csrParamVisitor visit, void* user);

/* Result of a bend characterisation (pressure sweep) by any model level. Caller-owned arrays of
 * capacity `cap`; `m` rows are filled. */
typedef struct csrBendCurve_ {
  size_t m, cap;
  double* pressure;     /* (m) MPa */
  double* angle_deg;    /* (m x 3) bending angle per segment, degrees */
  double* angle_total;  /* (m) total bending angle, degrees: the segments' sum as pushed; the FE
                         * and rom levels overwrite it with the base-to-tip rotation (joints) */
  double* tip;          /* (m x 3) tip position in the base frame (e1, e2, e3), mm */
  double p_until_angle; /* MPa at which the total angle reached --until-angle, or NAN */
} csrBendCurve;

csStatus csr_bendCurveInit(csrBendCurve* bc, size_t cap, csError* err);
void csr_bendCurveFree(csrBendCurve* bc);
/* Append one row; grows the arrays when full. */
csStatus csr_bendCurvePush(csrBendCurve* bc, double p, const double angle_deg[3],
                           const double tip[3], csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ACTUATOR_H */
