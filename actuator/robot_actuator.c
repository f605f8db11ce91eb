/* robot_actuator.c: actuator presets, named parameters, validation (see robot_actuator.h).
 * Preset values: docs/reference.md "Geometries" table; material and fibre data from the paper
 * (Sec. 3.3): C10 = 0.11, C20 = 0.02 MPa, rho = 1130e-12 t/mm^3; Kevlar E = 31067 MPa,
 * nu = 0.36, rho = 786e-12 t/mm^3, section radius 0.0889 mm. */
#include "robot_actuator.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char* const csr_actuator_param_names[] = {
    "S1", "S2", "S3", "n1", "n2", "n3", "LS12", "LS23", "a", "b", "c", "r1", "r2",
    "C10", "C20", "rho", "Ef", "nuf", "rhof", "rf", NULL};


/* pointer to the field a parameter name refers to, or NULL */
static double* paramField(csrActuator* act, const char* p) {
  static const char* const seg[] = {"S1", "S2", "S3"};
  static const char* const turns[] = {"n1", "n2", "n3"};
  for (int i = 0; i < CSR_NSEG; i++) {
    if (!strcmp(p, seg[i])) {
      return &act->S[i];
    }
    if (!strcmp(p, turns[i])) {
      return &act->n[i];
    }
  }
  if (!strcmp(p, "LS12")) return &act->LS[0];
  if (!strcmp(p, "LS23")) return &act->LS[1];
  if (!strcmp(p, "a")) return &act->a;
  if (!strcmp(p, "b")) return &act->b;
  if (!strcmp(p, "c")) return &act->c;
  if (!strcmp(p, "r1")) return &act->r1;
  if (!strcmp(p, "r2")) return &act->r2;
  if (!strcmp(p, "C10")) return &act->C10;
  if (!strcmp(p, "C20")) return &act->C20;
  if (!strcmp(p, "rho")) return &act->rho;
  if (!strcmp(p, "Ef")) return &act->Ef;
  if (!strcmp(p, "nuf")) return &act->nuf;
  if (!strcmp(p, "rhof")) return &act->rhof;
  if (!strcmp(p, "rf")) return &act->rf;
  return NULL;
}


csStatus csr_actuatorPreset(csrActuator* act, const char* name, csError* err) {
  memset(act, 0, sizeof *act);
  /* shared by all presets */
  act->a = 7.5;
  act->b = 4.0;
  act->c = 5.0;
  act->r1 = 2.0;
  act->r2 = 2.0;
  act->C10 = 0.11;
  act->C20 = 0.02;
  act->rho = 1130e-12;
  act->Ef = 31067.0;
  act->nuf = 0.36;
  act->rhof = 786e-12;
  act->rf = 0.0889;
  if (!strcmp(name, "fig1")) {
    act->S[0] = 40, act->S[1] = 50, act->S[2] = 50;
    act->n[0] = 24, act->n[1] = 30, act->n[2] = 30;
    act->LS[0] = 10, act->LS[1] = 6;
  } else if (!strcmp(name, "baseline")) {
    act->S[0] = act->S[1] = act->S[2] = 50;
    act->n[0] = act->n[1] = act->n[2] = 30;
    act->LS[0] = act->LS[1] = 6;
  } else if (!strcmp(name, "leg")) {
    /* robot leg, L = 166 mm; joint length 8 mm is docs/reference.md's assumption */
    act->S[0] = act->S[1] = act->S[2] = 50;
    act->n[0] = act->n[1] = act->n[2] = 30;
    act->LS[0] = act->LS[1] = 8;
  } else {
    return cs_errorSet(err, CS_ERR_ARG, "unknown actuator '%s' (expected fig1, baseline or leg)",
                       name);
  }
  snprintf(act->name, sizeof act->name, "%s", name);
  return CS_OK;
}


csStatus csr_actuatorSet(csrActuator* act, const char* pname, double value, csError* err) {
  double* f = paramField(act, pname);
  if (!f) {
    return cs_errorSet(err, CS_ERR_ARG,
                       "unknown actuator parameter '%s' (known: S1 S2 S3 n1 n2 n3 LS12 LS23 a b "
                       "c r1 r2 C10 C20 rho Ef nuf rhof rf)",
                       pname);
  }
  if (!isfinite(value)) {
    return cs_errorSet(err, CS_ERR_RANGE, "actuator parameter %s: value is not finite", pname);
  }
  *f = value;
  return CS_OK;
}


csStatus csr_actuatorSetString(csrActuator* act, const char* assignment, csError* err) {
  const char* eq = strchr(assignment, '=');
  if (!eq || eq == assignment || eq[1] == '\0') {
    return cs_errorSet(err, CS_ERR_ARG, "--set '%s': expected NAME=VALUE", assignment);
  }
  char name[32];
  size_t len = (size_t)(eq - assignment);
  if (len >= sizeof name) {
    return cs_errorSet(err, CS_ERR_ARG, "--set '%s': parameter name too long", assignment);
  }
  memcpy(name, assignment, len);
  name[len] = '\0';
  char* end = NULL;
  double v = strtod(eq + 1, &end);
  if (end == eq + 1 || *end != '\0') {
    return cs_errorSet(err, CS_ERR_ARG, "--set '%s': '%s' is not a number", assignment, eq + 1);
  }
  return csr_actuatorSet(act, name, v, err);
}


csStatus csr_actuatorValidate(const csrActuator* act, csError* err) {
  for (int i = 0; i < CSR_NSEG; i++) {
    if (!(act->S[i] > 0)) {
      return cs_errorSet(err, CS_ERR_RANGE, "actuator: S%d = %g must be > 0 mm", i + 1, act->S[i]);
    }
    if (!(act->n[i] >= 0)) {
      return cs_errorSet(err, CS_ERR_RANGE, "actuator: n%d = %g must be >= 0", i + 1, act->n[i]);
    }
    if (!(act->c > 0 && 2 * act->c < act->S[i])) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "actuator: c = %g mm must be > 0 and < S%d/2 = %g mm (chamber length "
                         "S - 2c must be positive)",
                         act->c, i + 1, act->S[i] / 2);
    }
  }
  for (int i = 0; i < CSR_NSEG - 1; i++) {
    if (!(act->LS[i] >= 0)) {
      return cs_errorSet(err, CS_ERR_RANGE, "actuator: LS%d%d = %g must be >= 0 mm", i + 1, i + 2,
                         act->LS[i]);
    }
  }
  if (!(act->r1 > 0 && act->b > act->r1)) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "actuator: chambers overlap (need r1 > 0 and b > r1, got r1 = %g, "
                       "b = %g mm)",
                       act->r1, act->b);
  }
  if (!(act->b + act->r1 < act->a)) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "actuator: chamber breaks the outer wall (need b + r1 < a, got %g + %g >= "
                       "%g mm)",
                       act->b, act->r1, act->a);
  }
  if (!(act->r2 >= 0 && act->r2 < act->a)) {
    return cs_errorSet(err, CS_ERR_RANGE, "actuator: fillet r2 = %g must be in [0, a) mm",
                       act->r2);
  }
  if (!(act->C10 > 0 && act->C20 >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "actuator: need C10 > 0 and C20 >= 0 (got %g, %g MPa)",
                       act->C10, act->C20);
  }
  if (!(act->rho > 0 && act->Ef > 0 && act->rf > 0 && act->rhof > 0 && act->nuf > -1 &&
        act->nuf < 0.5)) {
    return cs_errorSet(err, CS_ERR_RANGE, "actuator: densities, Ef and rf must be > 0, nuf in "
                                          "(-1, 0.5)");
  }
  return CS_OK;
}


void csr_actuatorSingleSegment(const csrActuator* act, csrActuator* one) {
  *one = *act;
  one->S[1] = one->S[2] = 0.0;
  one->LS[0] = one->LS[1] = 0.0;
  one->n[1] = one->n[2] = 0.0;
}


int csr_actuatorIsSingle(const csrActuator* act) {
  return act->S[1] == 0.0 && act->S[2] == 0.0 && act->LS[0] == 0.0 && act->LS[1] == 0.0;
}


csStatus csr_actuatorValidateSingle(const csrActuator* act, csError* err) {
  if (!csr_actuatorIsSingle(act)) {
    return csr_actuatorValidate(act, err);
  }
  if (act->n[1] != 0.0 || act->n[2] != 0.0) {
    return cs_errorSet(err, CS_ERR_RANGE, "actuator: a single segment has no fibres on II2, II3 "
                       "(got n2 = %g, n3 = %g)", act->n[1], act->n[2]);
  }
  /* segment II1 checked as one of three equal segments */
  csrActuator three = *act;
  three.S[1] = three.S[2] = act->S[0];
  three.n[1] = three.n[2] = act->n[0];
  return csr_actuatorValidate(&three, err);
}


double csr_actuatorLength(const csrActuator* act) {
  return act->S[0] + act->LS[0] + act->S[1] + act->LS[1] + act->S[2];
}


double csr_actuatorSegmentStart(const csrActuator* act, int s) {
  double x = 0;
  for (int i = 0; i < s; i++) {
    x += act->S[i] + act->LS[i];
  }
  return x;
}


double csr_actuatorOuterArea(const csrActuator* act) {
  /* square of side 2a minus the four corners cut by fillets of radius r2 */
  double side = 2 * act->a;
  return side * side - (4.0 - 3.14159265358979323846) * act->r2 * act->r2;
}


void csr_actuatorVisit(const csrActuator* act, csrParamVisitor visit, void* user) {
  csrActuator tmp = *act;
  for (int i = 0; csr_actuator_param_names[i]; i++) {
    visit(user, csr_actuator_param_names[i], *paramField(&tmp, csr_actuator_param_names[i]));
  }
}


csStatus csr_bendCurveInit(csrBendCurve* bc, size_t cap, csError* err) {
  memset(bc, 0, sizeof *bc);
  bc->p_until_angle = NAN;
  if (cap == 0) {
    cap = 16;
  }
  bc->pressure = malloc(cap * sizeof(double));
  bc->angle_deg = malloc(3 * cap * sizeof(double));
  bc->angle_total = malloc(cap * sizeof(double));
  bc->tip = malloc(3 * cap * sizeof(double));
  if (!bc->pressure || !bc->angle_deg || !bc->angle_total || !bc->tip) {
    csr_bendCurveFree(bc);
    return cs_errorSet(err, CS_ERR_MEMORY, "bend curve: out of memory");
  }
  bc->cap = cap;
  return CS_OK;
}


void csr_bendCurveFree(csrBendCurve* bc) {
  if (!bc) {
    return;
  }
  free(bc->pressure);
  free(bc->angle_deg);
  free(bc->angle_total);
  free(bc->tip);
  memset(bc, 0, sizeof *bc);
}


csStatus csr_bendCurvePush(csrBendCurve* bc, double p, const double angle_deg[3],
                           const double tip[3], csError* err) {
  if (bc->m == bc->cap) {
    size_t cap = 2 * bc->cap;
    double* np = realloc(bc->pressure, cap * sizeof(double));
    if (np) bc->pressure = np;
    double* na = realloc(bc->angle_deg, 3 * cap * sizeof(double));
    if (na) bc->angle_deg = na;
    double* nt = realloc(bc->angle_total, cap * sizeof(double));
    if (nt) bc->angle_total = nt;
    double* nx = realloc(bc->tip, 3 * cap * sizeof(double));
    if (nx) bc->tip = nx;
    if (!np || !na || !nt || !nx) {
      return cs_errorSet(err, CS_ERR_MEMORY, "bend curve: out of memory");
    }
    bc->cap = cap;
  }
  size_t i = bc->m++;
  bc->pressure[i] = p;
  bc->angle_total[i] = 0;
  for (int k = 0; k < 3; k++) {
    bc->angle_deg[3 * i + k] = angle_deg[k];
    bc->angle_total[i] += angle_deg[k];
    bc->tip[3 * i + k] = tip[k];
  }
  return CS_OK;
}
