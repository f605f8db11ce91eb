/* fem_rom_sway.c: the foot's compliance of the FE leg and of its reduced model under an axial
 * load (fem_rom_sway.h). */
#include "fem_rom_sway.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_assembly.h"
#include "fem_linsolve.h"

csStatus csf_swayFunctionals(const csfActuatorFE* fe, double* c_lat, double* c_rot,
                             double axis[3], csError* err) {
  const csfMesh* me = fe->mesh;
  const int ndof = fe->model->ndof;
  memset(c_lat, 0, (size_t)ndof * sizeof(double));
  memset(c_rot, 0, (size_t)ndof * sizeof(double));
  double wsum = 0, xbar = 0, zbar = 0;
  for (int a = 0; a < me->nnode; a++) {
    const double w = fe->tip_unit[3 * a];
    wsum += w, xbar += w * me->x[3 * a], zbar += w * me->x[3 * a + 2];
  }
  if (!(wsum > 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "sway: the model has no tip face");
  }
  xbar /= wsum, zbar /= wsum;
  const double s = zbar >= 0 ? 1.0 : -1.0; /* the clamp is the face at z = 0 (fem_actuator.c) */
  double S = 0;
  for (int a = 0; a < me->nnode; a++) {
    const double dx = me->x[3 * a] - xbar;
    S += fe->tip_unit[3 * a] * dx * dx;
  }
  if (!(S > 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "sway: the tip face has no extent along e1");
  }
  for (int a = 0; a < me->nnode; a++) {
    const double w = fe->tip_unit[3 * a];
    c_lat[3 * a] = w / wsum;
    c_rot[3 * a + 2] = -s * w * (me->x[3 * a] - xbar) / S;
  }
  axis[0] = 0, axis[1] = 0, axis[2] = s;
  return CS_OK;
}

csStatus csf_romSwayCompliance(csfRomActuator* ra, const double* c_lat, const double* c_rot,
                               const double axis[3], double P, double C[3], csError* err) {
  const csfRom* r = ra->rom;
  csfRomData* d = ra->d;
  const int n = r->n;
  const double p[CSR_NSEG * CSR_NCHAMBER] = {0};
  const double g[3] = {0, 0, 0};
  const double F[3] = {-P * axis[0], -P * axis[1], -P * axis[2]};
  csStatus st = csf_romActuatorSolve(ra, p, g, F, err);
  if (st != CS_OK) {
    return st;
  }
  double* buf = malloc(4 * (size_t)n * sizeof(double));
  if (!buf) {
    return cs_errorSet(err, CS_ERR_MEMORY, "sway: out of memory (%d values)", 4 * n);
  }
  double* f1 = buf, *f2 = buf + n, *x1 = buf + 2 * (size_t)n, *x2 = buf + 3 * (size_t)n;
  csf_romProject(r, c_lat, f1);
  csf_romProject(r, c_rot, f2);
  csfRomLoad ld;
  csf_romActuatorLoad(ra, p, g, F, &ld);
  const int sync = d->sync;
  d->sync = 1; /* the exact derivative of r at the converged states */
  const int ev = csf_romEvaluate(r, d, &ld, 1);
  d->sync = sync;
  if (ev != 0) {
    free(buf);
    return cs_errorSet(err, CS_ERR_DIVERGED, "sway: the reduced state at %g N is not physical",
                       P);
  }
  st = csf_romFactorTangent(r, d, err); /* no secant pairs after it: H = K^-1 */
  if (st == CS_OK) {
    memcpy(x1, f1, (size_t)n * sizeof(double));
    memcpy(x2, f2, (size_t)n * sizeof(double));
    csf_romQuasiNewtonApply(r, d, x1);
    csf_romQuasiNewtonApply(r, d, x2);
    double c11 = 0, c12 = 0, c21 = 0, c22 = 0;
    for (int i = 0; i < n; i++) {
      c11 += f1[i] * x1[i], c12 += f1[i] * x2[i], c21 += f2[i] * x1[i], c22 += f2[i] * x2[i];
    }
    C[0] = c11, C[1] = 0.5 * (c12 + c21), C[2] = c22;
  }
  free(buf);
  return st;
}

csStatus csf_feSwayCompliance(csfActuatorFE* fe, csfData* d, const csfNewtonOptions* nopt,
                              const double* c_lat, const double* c_rot, const double axis[3],
                              double P_from, double P, double C[3], int* neg, int* newton,
                              csError* err) {
  csfModel* m = fe->model;
  *newton = 0;
  /* the dead load ramped as fem_bend.c's stageDeadLoads: a step halved on failure, grown by
   * 1.5 after an easy one (<= 5 iterations) */
  double s = 0.0, ds = 1.0;
  csError lerr = {0};
  while (s < 1.0) {
    const double next = fmin(s + ds, 1.0);
    const double Pn = P_from + next * (P - P_from);
    const double F[3] = {-Pn * axis[0], -Pn * axis[1], -Pn * axis[2]};
    csf_actuatorSetTipForce(fe, F);
    int it = 0;
    const csStatus gst = csf_newtonSolve(m, d, 0.0, nopt, &it, &lerr);
    *newton += it;
    if (gst == CS_OK) {
      s = next;
      ds *= it <= 5 ? 1.5 : 1.0;
    } else if ((ds *= 0.5) < 1e-3) {
      return cs_errorSet(err, CS_ERR_DIVERGED, "sway: the FE found no equilibrium beyond %.4g N "
                         "of the axial load: %s", P_from + s * (P - P_from), lerr.msg);
    }
  }
  csf_dataSyncVolume(m, d); /* theta = v/V: K is the exact derivative of R */
  if (csf_assemble(m, d, 0.0, 1) != 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "sway: the FE state at %g N is not physical", P);
  }
  if (csf_linSolverFactor(d->ls, d->kval) != 0) {
    return cs_errorSet(err, CS_ERR_SOLVER, "sway: the FE tangent at %g N is singular", P);
  }
  d->have_factor = 0; /* the factor is the sway's: Newton factors its own next time */
  *neg = csf_linSolverNegativePivots(d->ls);
  const int ndof = m->ndof;
  double* x = malloc(2 * (size_t)ndof * sizeof(double));
  if (!x) {
    return cs_errorSet(err, CS_ERR_MEMORY, "sway: out of memory (%d values)", 2 * ndof);
  }
  memcpy(x, c_lat, (size_t)ndof * sizeof(double));
  memcpy(x + ndof, c_rot, (size_t)ndof * sizeof(double));
  csStatus st = CS_OK;
  if (csf_linSolverSolve(d->ls, x) != 0 || csf_linSolverSolve(d->ls, x + ndof) != 0) {
    st = cs_errorSet(err, CS_ERR_SOLVER, "sway: the FE solve at %g N failed", P);
  } else {
    double c11 = 0, c12 = 0, c21 = 0, c22 = 0;
    for (int i = 0; i < ndof; i++) {
      c11 += c_lat[i] * x[i], c12 += c_lat[i] * x[ndof + i];
      c21 += c_rot[i] * x[i], c22 += c_rot[i] * x[ndof + i];
    }
    C[0] = c11, C[1] = 0.5 * (c12 + c21), C[2] = c22;
  }
  free(x);
  return st;
}
