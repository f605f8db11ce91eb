/* fem_actuator.c: the actuator's FE model: mesh, clamp, chambers, fibres, loads
 * (fem_actuator.h).
 *
 * Fibres: two counter-wound helices per segment (n turns each over S) on the rounded-square
 * perimeter, inset CSF_FIBRE_INSET below the outer surface so the tie points lie inside the
 * host elements. */
#define _POSIX_C_SOURCE 200809L /* sysconf */
#include "fem_actuator.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core_math.h"
#include "fem_assembly.h"
#include "fem_element.h"

#define CSF_FIBRE_INSET 0.2 /* mm below the outer surface (fibre radius 0.089 mm) */
#define CSF_PLANE_TOL 1e-6  /* mm: nodes on the clamped face */
/* default fibre point spacing l_fibre = l_soft / 8 (0.5 mm at l_soft 4). Measured on the leg at
 * l_soft 4, total bend at 0.1 MPa (fem/README.md "Fibre discretisation"): split fibres at
 * l_fibre 1.5 / 0.75 / 0.5 / 0.3 mm give 49.94 / 50.23 / 50.43 / 50.55 deg (from below, towards
 * ~50.7), the 20-node ties of the paper's pairing l_fibre = 0.4 l_soft - 0.1 = 1.5 mm gave
 * 51.52 (0.75 mm: 51.05, from above): 0.5 mm is within ~0.5 % of the fibre-converged value at
 * no extra fill (the split keeps each fibre element in one tetrahedron) */
#define CSF_FIBRE_SIZE_REL 0.125


csfActuatorSpec csf_actuatorSpecDefault(void) {
  csfActuatorSpec s;
  memset(&s, 0, sizeof s);
  for (int k = 0; k < CSR_NSEG; k++) {
    s.ratio[k][0] = s.ratio[k][1] = 1.0; /* Omega1 & Omega2 */
  }
  s.mesh_size = 4.0;
  s.fibre_size = 0.0;
  s.fibres = 1;
  /* tension-only: a truss without bending stiffness that carries compression goes unstable in
   * the soft matrix at a wavelength the mesh sets (split fibres: a critical point near 0.19 MPa
   * for Omega1 & Omega2 of the baseline, moving with l_soft; fem/README.md "The stall is a
   * critical point"); thread buckles instead. With it the baseline reaches 360 deg at
   * 0.3939 MPa (linear 20-node ties: 0.3875) */
  s.fibre_compression = 0;
  s.fibre_geo_tension = 0;
  s.fibre_split = 1;
  s.form = CSF_FORM_MIXED_P0;
  s.work_stem = "crawlsim_fe";
  return s;
}

double csf_actuatorFibreSize(const csfActuatorSpec* sp) {
  return sp->fibre_size > 0 ? sp->fibre_size : CSF_FIBRE_SIZE_REL * sp->mesh_size;
}


/* point at arc length s on the rounded square of half side h, corner radius r (CCW from (h,0)) */
static void roundedSquarePoint(double h, double r, double s, double p[2]) {
  const double ls = 2.0 * (h - r), la = 0.5 * CS_PI * r, P = 4 * ls + 4 * la;
  s = fmod(s, P);
  if (s < 0) {
    s += P;
  }
  /* start in the middle of the +x side: shift so that piece 0 starts at the corner (h, -(h-r)) */
  s += 0.5 * ls;
  if (s >= P) {
    s -= P;
  }
  for (int side = 0; side < 4; side++) {
    /* side k: straight piece then corner; rotate the +x side by k * 90 deg */
    double q[2];
    if (s <= ls) {
      q[0] = h, q[1] = -(h - r) + s;
    } else if (s <= ls + la) {
      double t = (s - ls) / (r > 0 ? r : 1.0);
      q[0] = (h - r) + r * cos(t), q[1] = (h - r) + r * sin(t);
    } else {
      s -= ls + la;
      continue;
    }
    double c = cos(side * 0.5 * CS_PI), sn = sin(side * 0.5 * CS_PI);
    p[0] = c * q[0] - sn * q[1];
    p[1] = sn * q[0] + c * q[1];
    return;
  }
  p[0] = h, p[1] = -(h - r);
}


/* embed the two counter-wound helices of every segment with n > 0 */
static csStatus addFibres(const csrActuator* act, csfModel* m, double lf, double inset,
                          int turn, csError* err) {
  /* the rounded square is invariant under quarter turns: turning the start turns each helix */
  const double ct = cos(turn * 0.5 * CS_PI), stn = sin(turn * 0.5 * CS_PI);
  const double h = act->a - inset, r = fmax(act->r2 - inset, 0.0);
  const double P = 8.0 * (h - r) + 2.0 * CS_PI * r;
  for (int s = 0; s < CSR_NSEG; s++) {
    if (!(act->n[s] > 0)) {
      continue;
    }
    const double z0 = csr_actuatorSegmentStart(act, s), S = act->S[s];
    const double len = sqrt(pow(act->n[s] * P, 2) + S * S);
    const int np = (int)ceil(len / lf) + 1;
    double* pts = malloc((size_t)np * 3 * sizeof(double));
    if (!pts) {
      return cs_errorSet(err, CS_ERR_MEMORY, "fem_actuator: out of memory (fibre)");
    }
    for (int hand = -1; hand <= 1; hand += 2) {
      for (int k = 0; k < np; k++) {
        double t = (double)k / (np - 1), p2[2];
        roundedSquarePoint(h, r, hand * act->n[s] * P * t, p2);
        pts[3 * k] = ct * p2[0] - stn * p2[1];
        pts[3 * k + 1] = stn * p2[0] + ct * p2[1];
        pts[3 * k + 2] = z0 + t * S;
      }
      csStatus st = csf_modelAddFibre(m, np, pts, act->Ef, act->rf, err);
      if (st != CS_OK) {
        free(pts);
        return st;
      }
    }
    free(pts);
  }
  return CS_OK;
}


void csf_actuatorFEDestroy(csfActuatorFE* fe) {
  if (!fe) {
    return;
  }
  csf_gaugesDestroy(fe->gauges);
  csf_modelDestroy(fe->model);
  csf_meshDestroy(fe->mesh);
  free(fe->tip_unit);
  memset(fe, 0, sizeof *fe);
}


void csf_actuatorSetTipForce(csfActuatorFE* fe, const double F[3]) {
  csfModel* m = fe->model;
  for (int i = 0; i < m->ndof; i++) {
    m->f_dead[i] = fe->tip_unit[i] * F[i % 3];
  }
}


/* nodal weights of a unit uniform traction on the (flat) tip face: w_a = int N_a dA over the
 * reference faces, from the face kernel with p = 1 (its force is -p int N_a n dA, n = +e3) */
static csStatus tipWeights(csfActuatorFE* fe, csError* err) {
  const csfMesh* me = fe->mesh;
  fe->tip_unit = calloc((size_t)fe->model->ndof, sizeof(double));
  if (!fe->tip_unit) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_actuator: out of memory");
  }
  double area = 0;
  for (int f = 0; f < me->nface; f++) {
    if (me->face_tag[f] != CSF_TAG_TIP) {
      continue;
    }
    double xf[18], fe1[18], v;
    for (int a = 0; a < 6; a++) {
      memcpy(xf + 3 * a, me->x + 3 * me->face[6 * f + a], 3 * sizeof(double));
    }
    csf_faceKernel(xf, 1.0, fe1, NULL, &v);
    for (int a = 0; a < 6; a++) {
      const double w = -fe1[3 * a + 2];
      area += w;
      for (int i = 0; i < 3; i++) {
        fe->tip_unit[3 * me->face[6 * f + a] + i] += w;
      }
    }
  }
  if (!(area > 0)) {
    return cs_errorSet(err, CS_ERR_EXTERNAL, "fem_actuator: the mesh has no tip face");
  }
  for (int i = 0; i < fe->model->ndof; i++) {
    fe->tip_unit[i] /= area;
  }
  fe->tip_area = area;
  return CS_OK;
}


/* the pressurised chambers' count and the reference bending axis: e3 x (away from the pressure
 * moment sum_j r_j (x_j, y_j) of the chambers' centres), e2 when it vanishes (elongation) */
static void pressureAxis(const csrActuator* act, const csfActuatorSpec* sp, csfActuatorFE* fe) {
  static const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, -1, 1};
  double cc[2] = {0, 0};
  fe->ncham = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      const double r = sp->ratio[s][j];
      if (r == 0.0 || !(act->S[s] > 0)) {
        continue;
      }
      cc[0] += r * sx[j], cc[1] += r * sy[j];
      fe->ncham++;
    }
  }
  csu_set3(fe->axis, 0, 1, 0);
  if (hypot(cc[0], cc[1]) > 1e-12) {
    double dir[3] = {-cc[0], -cc[1], 0}, e3[3] = {0, 0, 1};
    csu_normalize3(dir);
    csu_cross3(fe->axis, e3, dir);
  }
}


/* the tip face's traction weights and the measurement gauges of the mesh */
static csStatus tipAndGauges(const csrActuator* act, csfActuatorFE* fe, csError* err) {
  csStatus st = tipWeights(fe, err);
  if (st == CS_OK) {
    fe->gauges = csf_gaugesCreate(act, fe->mesh, err);
    st = fe->gauges ? CS_OK : (err ? err->status : CS_ERR_MEMORY);
  }
  return st;
}


void csf_actuatorWalls(const csrActuator* act, double l_soft, csfWalls* w) {
  const double a = act->a, b = act->b, r1 = act->r1, r2 = act->r2;
  /* chamber centre (b, b) to the outer boundary: the straight side at a - b, or the fillet arc
   * (centre (a - r2, a - r2), radius r2) when the chamber sits beyond the fillet's centre */
  double d = a - b;
  if (b > a - r2) {
    d = fmin(d, r2 - sqrt(2.0) * (b - (a - r2)));
  }
  w->outer = d - r1;
  w->between = 2.0 * (b - r1);
  w->cap = act->c;
  w->mesh = fmin(l_soft, 2.0 * CS_PI * r1 / CSF_CHAMBER_SEGMENTS);
}


/* a factorisation may take this share of the machine's memory (the rest: the mesh, the model,
 * the fibres, the operating system and another job) */
#define CSF_MEM_FRACTION 0.75


/* physical memory of this machine, B (0 when unknown: no refusal) */
static double physicalMemory(void) {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? (double)pages * (double)size : 0.0;
}


void csf_actuatorEstimate(const csrActuator* act, double l_soft, csfMeshEstimate* e) {
  double V = csr_actuatorOuterArea(act) * csr_actuatorLength(act);
  for (int s = 0; s < CSR_NSEG; s++) {
    if (act->S[s] > 0) { /* a single segment (csr_actuatorSingleSegment) has S2 = S3 = 0 */
      V -= CSR_NCHAMBER * CS_PI * act->r1 * act->r1 * (act->S[s] - 2 * act->c);
    }
  }
  e->volume = V;
  e->tet10 = V / (0.2 * l_soft * l_soft * l_soft);
  e->nodes = 1.6 * e->tet10;
  e->dofs = 3.0 * e->nodes;
  e->entries = 3.4e7 * pow(e->dofs / 75801.0, 4.0 / 3.0);
  e->bytes = 20.0 * e->entries;
}


csStatus csf_actuatorFECreate(const csrActuator* act, const csfActuatorSpec* sp,
                              csfActuatorFE* fe, csError* err) {
  memset(fe, 0, sizeof *fe);
  csStatus st = csr_actuatorValidateSingle(act, err);
  if (st != CS_OK) {
    return st;
  }
  if (!(sp->mesh_size > 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_actuator: mesh size must be > 0");
  }
  if (sp->fibre_turn < -3 || sp->fibre_turn > 3) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_actuator: fibre turn %d quarter turns is outside "
                       "-3..3", sp->fibre_turn);
  }
  /* walls the mesh cannot resolve: refused before gmsh runs, naming the parameters */
  csfWalls w;
  csf_actuatorWalls(act, sp->mesh_size, &w);
  const double tmin = CSF_WALL_MIN_REL * w.mesh;
  if (w.outer < tmin) {
    return cs_errorSet(err, CS_ERR_RANGE, "fem_actuator: the wall between a chamber and the "
                       "outer surface is %.3g mm thick (a = %g, b = %g, r1 = %g, r2 = %g mm): "
                       "below %g of the %.3g mm chamber-wall elements, the mesh cannot resolve it",
                       w.outer, act->a, act->b, act->r1, act->r2, CSF_WALL_MIN_REL, w.mesh);
  }
  if (w.between < tmin) {
    return cs_errorSet(err, CS_ERR_RANGE, "fem_actuator: the wall between adjacent chambers is "
                       "%.3g mm thick (2 (b - r1), b = %g, r1 = %g mm): below %g of the %.3g mm "
                       "chamber-wall elements, the mesh cannot resolve it",
                       w.between, act->b, act->r1, CSF_WALL_MIN_REL, w.mesh);
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      if (!(isfinite(sp->ratio[s][j]) && sp->ratio[s][j] >= 0)) {
        return cs_errorSet(err, CS_ERR_ARG, "fem_actuator: chamber pressure ratio of II%d-O%d "
                           "must be finite and >= 0 (got %g)", s + 1, j + 1, sp->ratio[s][j]);
      }
    }
  }
  /* a mesh far too fine for this machine: refused with the estimate before gmsh runs (gmsh
   * itself would take minutes to hours to make it, and the factorisation cannot fit) */
  csfMeshEstimate est;
  csf_actuatorEstimate(act, sp->mesh_size, &est);
  const double mem = physicalMemory();
  /* distributed factors: this machine holds its ranks' share of them */
  const int ranks = sp->mpi_ranks > 1 ? sp->mpi_ranks : 1;
  const int local = sp->mpi_ranks_local >= 1 && sp->mpi_ranks_local <= ranks ? sp->mpi_ranks_local
                                                                            : ranks;
  const double here = est.bytes * (double)local / (double)ranks;
  if (mem > 0 && here > CSF_MEM_FRACTION * mem) {
    /* bytes ~ l^-4 (dofs ~ l^-3, entries ~ dofs^(4/3)): the finest l_soft that fits */
    const double lmin = sp->mesh_size * pow(here / (CSF_MEM_FRACTION * mem), 0.25);
    char share[96] = "";
    if (ranks > 1) {
      snprintf(share, sizeof share, " (%d of its %d MPI ranks on this machine)", local, ranks);
    }
    return cs_errorSet(err, CS_ERR_RANGE, "fem_actuator: l_soft %g mm gives at least %.2g Tet10 "
                       "(%.2g dofs), whose factorisation needs about %.3g GB%s against %.3g GB of "
                       "memory on this machine: refused (l_soft >= %.2g mm may fit)",
                       sp->mesh_size, est.tet10, est.dofs, here / 1e9, share, mem / 1e9, lmin);
  }
  const char* stem = sp->work_stem ? sp->work_stem : "crawlsim_fe";
  fe->mesh = sp->mesh_symmetric ? csf_meshActuatorSymmetric(act, sp->mesh_size, stem, err)
                                : csf_meshActuator(act, sp->mesh_size, stem, err);
  if (!fe->mesh) {
    return err ? err->status : CS_ERR_EXTERNAL;
  }
  csfMaterial mat = csf_materialDefault(act->C10, act->C20, act->rho);
  mat.form = sp->form;
  fe->model = csf_modelCreate(fe->mesh, &mat, err);
  if (!fe->model) {
    csf_actuatorFEDestroy(fe);
    return err ? err->status : CS_ERR_ARG;
  }
  csfModel* m = fe->model;
  for (int i = 0; i < fe->mesh->nnode; i++) {
    if (fabs(fe->mesh->x[3 * i + 2]) < CSF_PLANE_TOL) {
      m->fixed[3 * i] = m->fixed[3 * i + 1] = m->fixed[3 * i + 2] = 1;
    }
  }
  /* chambers; the pressure moment fixes the reference bending axis (pressureAxis) */
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      const double r = sp->ratio[s][j];
      if (r == 0.0 || !(act->S[s] > 0)) { /* vented, or a segment a single one does not have */
        continue;
      }
      if (csf_modelAddPressure(m, CSF_TAG_CHAMBER(s, j + 1), r) <= 0) {
        csf_actuatorFEDestroy(fe);
        return cs_errorSet(err, CS_ERR_EXTERNAL, "fem_actuator: chamber %d of segment %d has no "
                           "tagged faces in the mesh", j + 1, s + 1);
      }
    }
  }
  pressureAxis(act, sp, fe);
  for (int i = 0; i < 3; i++) {
    m->gravity[i] = sp->gravity[i];
  }
  if (sp->fibres) {
    const double lf = csf_actuatorFibreSize(sp);
    m->fib_split = sp->fibre_split;
    st = addFibres(act, m, lf, CSF_FIBRE_INSET, sp->fibre_turn, err);
    if (st != CS_OK) {
      csf_actuatorFEDestroy(fe);
      return st;
    }
    m->fib_tension_only = !sp->fibre_compression;
    m->fib_geo_tension = sp->fibre_geo_tension;
  }
  st = csf_modelFinalize(m, err);
  if (st == CS_OK) {
    st = tipAndGauges(act, fe, err);
  }
  if (st != CS_OK) {
    csf_actuatorFEDestroy(fe);
    return st;
  }
  csf_actuatorSetTipForce(fe, sp->tip_force);
  return CS_OK;
}


csStatus csf_actuatorFEFromModel(const csrActuator* act, const csfActuatorSpec* spec,
                                 csfMesh* mesh, csfModel* model, csfActuatorFE* fe,
                                 csError* err) {
  memset(fe, 0, sizeof *fe);
  fe->mesh = mesh;
  fe->model = model;
  if (!mesh || !model || model->mesh != mesh) {
    csf_actuatorFEDestroy(fe);
    return cs_errorSet(err, CS_ERR_ARG, "fem_actuator: a model needs its own mesh");
  }
  pressureAxis(act, spec, fe);
  const csStatus st = tipAndGauges(act, fe, err);
  if (st != CS_OK) {
    csf_actuatorFEDestroy(fe);
  }
  return st;
}
