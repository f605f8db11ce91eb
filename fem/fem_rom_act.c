/* fem_rom_act.c: the reduced actuator from its basis and weights files (fem_rom_act.h).
 *
 * Rationale. The reduced model needs the FE model's reference geometry, fibres and faces, not
 * its solver: the actuator is meshed again from its parameters (gmsh is deterministic for the
 * same .geo), and a mesh signature stored with the basis (node and element counts, the sum and
 * sum of squares of the coordinates) refuses a basis made on another mesh. The load is ramped
 * from the last solved one as the FE's sweep does (fem_bend.c): the reduced Newton, like the
 * FE's, needs load steps that keep it near the equilibrium path (test_fem_rom). */
#include "fem_rom_act.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "fem_mesh.h"

#define RAMP_GROW_ITERS 6  /* grow the ramp step after Newton solves this easy */
#define RAMP_MIN_REL 1e-4  /* smallest ramp step (fraction of the load change) */
#define SIGNATURE_TOL 1e-9 /* relative agreement of the mesh signature */

static int readAttr(hid_t f, const char* name, double* v) {
  return H5Aexists(f, name) > 0 && H5LTget_attribute_double(f, "/", name, v) >= 0;
}

double csf_romBasisMeshSize(const char* basis_path, csError* err) {
  double l = NAN;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(basis_path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f >= 0) {
      if (!readAttr(f, "fe_mesh_size_mm", &l)) {
        l = NAN;
      }
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  if (isnan(l)) {
    cs_errorSet(err, CS_ERR_IO, "%s: not a reduced-model basis file (no fe_mesh_size_mm)",
                basis_path);
  }
  return l;
}

/* read a whole dataset of doubles (rank 1-3); NULL if absent or of another size than want
 * (want 0: any), *count gets the element count */
static double* readDoubles(hid_t f, const char* name, size_t want, size_t* count) {
  if (H5LTfind_dataset(f, name) <= 0) {
    return NULL;
  }
  int rank = 0;
  if (H5LTget_dataset_ndims(f, name, &rank) < 0 || rank < 1 || rank > 3) {
    return NULL;
  }
  hsize_t dims[3] = {1, 1, 1};
  H5T_class_t cls;
  size_t sz;
  if (H5LTget_dataset_info(f, name, dims, &cls, &sz) < 0) {
    return NULL;
  }
  const size_t n = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2];
  if (want && n != want) {
    return NULL;
  }
  double* v = malloc((n > 0 ? n : 1) * sizeof(double));
  if (v && H5LTread_dataset_double(f, name, v) < 0) {
    free(v);
    return NULL;
  }
  *count = n;
  return v;
}

static csStatus readWeights(csfRomActuator* ra, const char* path, csError* err) {
  csStatus st = CS_OK;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) {
      st = cs_errorSet(err, CS_ERR_IO, "%s: cannot open the weights file", path);
    }
    static const char* const kId[CSF_ROM_NSET] = {"tet_id", "fibre_id", "face_id"};
    static const char* const kW[CSF_ROM_NSET] = {"tet_w", "fibre_w", "face_w"};
    for (int s = 0; f >= 0 && st == CS_OK && s < CSF_ROM_NSET; s++) {
      size_t ni = 0, nw = 0;
      double* id = readDoubles(f, kId[s], 0, &ni);
      double* w = id ? readDoubles(f, kW[s], ni, &nw) : NULL;
      if (id && !w) {
        st = cs_errorSet(err, CS_ERR_IO, "%s: %s has no %s of the same length", path, kId[s],
                         kW[s]);
      } else if (id) {
        int* idx = malloc((ni > 0 ? ni : 1) * sizeof(int));
        if (!idx) {
          st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
        } else {
          for (size_t k = 0; k < ni; k++) {
            idx[k] = (int)id[k];
          }
          st = csf_romSetWeights(ra->rom, (csfRomSet)s, (int)ni, idx, w, err);
          if (st != CS_OK) {
            char m[sizeof err->msg];
            memcpy(m, err->msg, sizeof m);
            cs_errorSet(err, st, "%s: %.400s", path, m);
          }
          free(idx);
        }
      }
      free(id);
      free(w);
    }
    if (f >= 0) {
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  return st;
}

/* P [ntet, m] of a mixed basis file into the rom (none: displacement-only, CS_OK), or with
 * `fibre` the fibre strain basis Qf [nfib, mf] (none: the FE's fibres, CS_OK) */
static csStatus readPressureBasis(const char* basis_path, csfRom* rom, int fibre, csError* err) {
  double m_attr = 0;
  double* P = NULL;
  size_t np = 0;
  const size_t rows = fibre ? (size_t)rom->fem->nfib : (size_t)rom->fem->mesh->ntet;
  const char* attr = fibre ? "mf" : "m";
  const char* name = fibre ? "Qf" : "P";
  int bad = 0;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(basis_path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f >= 0) {
      if (readAttr(f, attr, &m_attr) && m_attr > 0) {
        P = readDoubles(f, name, rows * (size_t)m_attr, &np);
        bad = !P;
      }
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  if (bad) {
    return cs_errorSet(err, CS_ERR_IO, "%s: attribute %s = %g but no dataset %s of %zu x %g "
                       "(the %s)", basis_path, attr, m_attr, name, rows, m_attr,
                       fibre ? "fibre strain basis" : "element pressure basis");
  }
  if (!P) {
    return CS_OK;
  }
  const csStatus st = fibre ? csf_romSetFibreBasis(rom, (int)m_attr, P, err)
                            : csf_romSetPressureBasis(rom, (int)m_attr, P, err);
  free(P);
  return st;
}

static csStatus finish(csfRomActuator* ra, csError* err);

csStatus csf_romActuatorCreate(const csrActuator* act, const csfActuatorSpec* spec,
                               const char* basis_path, const char* weights_path,
                               csfRomActuator* ra, csError* err) {
  memset(ra, 0, sizeof *ra);
  snprintf(ra->basis_path, sizeof ra->basis_path, "%s", basis_path);
  /* the basis and its mesh signature */
  double n_attr = 0, sig[4] = {0, 0, 0, 0}, l = 0;
  double* V = NULL;
  size_t nv = 0;
  csStatus st = CS_OK;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(basis_path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) {
      st = cs_errorSet(err, CS_ERR_IO, "%s: cannot open the basis file", basis_path);
    } else {
      if (!readAttr(f, "n", &n_attr) || !readAttr(f, "fe_mesh_size_mm", &l) ||
          !readAttr(f, "mesh_nnode", &sig[0]) || !readAttr(f, "mesh_ntet", &sig[1]) ||
          !readAttr(f, "mesh_x_sum", &sig[2]) || !readAttr(f, "mesh_x_sq", &sig[3])) {
        st = cs_errorSet(err, CS_ERR_IO, "%s: not a reduced-model basis file (attributes n, "
                         "fe_mesh_size_mm, mesh_nnode, mesh_ntet, mesh_x_sum, mesh_x_sq)",
                         basis_path);
      } else {
        V = readDoubles(f, "V", 0, &nv);
        if (!V) {
          st = cs_errorSet(err, CS_ERR_IO, "%s: no dataset V", basis_path);
        }
      }
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  if (st != CS_OK) {
    free(V);
    return st;
  }
  if (fabs(l - spec->mesh_size) > 1e-12 * l || !spec->mesh_symmetric) {
    free(V);
    return cs_errorSet(err, CS_ERR_ARG, "%s: the basis was made on the symmetric mesh of l_soft "
                       "%g mm, not on this one (l_soft %g, symmetric %d)", basis_path, l,
                       spec->mesh_size, spec->mesh_symmetric);
  }
  st = csf_actuatorFECreate(act, spec, &ra->fe, err);
  if (st != CS_OK) {
    free(V);
    return st;
  }
  const csfMesh* me = ra->fe.mesh;
  double xs = 0, xq = 0;
  for (int i = 0; i < 3 * me->nnode; i++) {
    xs += me->x[i], xq += me->x[i] * me->x[i];
  }
  const int n = (int)n_attr;
  if (me->nnode != (int)sig[0] || me->ntet != (int)sig[1] ||
      fabs(xs - sig[2]) > SIGNATURE_TOL * fabs(sig[3]) ||
      fabs(xq - sig[3]) > SIGNATURE_TOL * fabs(sig[3]) || nv != (size_t)ra->fe.model->ndof * n) {
    csf_romActuatorDestroy(ra);
    free(V);
    return cs_errorSet(err, CS_ERR_ARG, "%s: the basis was made on another mesh (%g nodes, %g "
                       "Tet10, coordinate sums %.10g, %.10g; this one: %d, %d, %.10g, %.10g)",
                       basis_path, sig[0], sig[1], sig[2], sig[3], me->nnode, me->ntet, xs, xq);
  }
  ra->rom = csf_romCreate(ra->fe.model, n, V, err);
  free(V);
  if (!ra->rom) {
    csf_romActuatorDestroy(ra);
    return err->status;
  }
  /* the mixed model's element pressure basis, when the file has one (tools/rom_basis.py
   * --mixed: P [ntet, m], attribute m) and the fibre strain basis (--fibre-modes: Qf [nfib,
   * mf], attribute mf) */
  st = readPressureBasis(basis_path, ra->rom, 0, err);
  if (st == CS_OK) {
    st = readPressureBasis(basis_path, ra->rom, 1, err);
  }
  if (st != CS_OK) {
    csf_romActuatorDestroy(ra);
    return st;
  }
  /* the twelve chambers' pressure loads in closed form (fem_rom.h: exact, conservative) */
  int* fch = malloc((size_t)me->nface * sizeof(int) + 1);
  if (!fch) {
    csf_romActuatorDestroy(ra);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_act: out of memory");
  }
  for (int f = 0; f < me->nface; f++) {
    const int tag = me->face_tag[f], seg = tag / 10 - 11, j = tag % 10 - 1;
    fch[f] = tag >= CSF_TAG_CHAMBER(0, 1) && seg >= 0 && seg < CSR_NSEG && j >= 0 &&
                     j < CSR_NCHAMBER
                 ? CSR_NCHAMBER * seg + j
                 : -1;
  }
  st = csf_romChamberTensors(ra->rom, CSR_NSEG * CSR_NCHAMBER, fch, err);
  free(fch);
  if (st != CS_OK) {
    csf_romActuatorDestroy(ra);
    return st;
  }
  st = finish(ra, err);
  if (st != CS_OK) {
    return st;
  }
  if (weights_path && (st = readWeights(ra, weights_path, err)) != CS_OK) {
    csf_romActuatorDestroy(ra);
    return st;
  }
  return CS_OK;
}

/* the reduced actuator's state and load maps once ra->fe and ra->rom exist (freed on failure) */
static csStatus finish(csfRomActuator* ra, csError* err) {
  const int n = ra->rom->n;
  ra->d = csf_romDataCreate(ra->rom, err);
  const size_t nd = (size_t)ra->fe.model->ndof;
  ra->face_p = calloc((size_t)ra->fe.mesh->nface + 1, sizeof(double));
  ra->Ftip = calloc(3 * (size_t)n, sizeof(double));
  ra->f_dead = calloc((size_t)n, sizeof(double));
  ra->u = calloc(nd, sizeof(double));
  ra->q_conv = calloc((size_t)n, sizeof(double));
  ra->q_prev = calloc((size_t)n, sizeof(double));
  ra->nhist = 0;
  ra->k_lag = CSF_ROM_ACT_K_LAG;
  ra->bfgs = CSF_ROM_ACT_BFGS;
  ra->rtol = CSF_ROM_ACT_RTOL;
  double* tmp = calloc(nd, sizeof(double));
  double* fr = calloc((size_t)n, sizeof(double));
  if (!ra->d || !ra->face_p || !ra->Ftip || !ra->f_dead || !ra->u || !ra->q_conv || !ra->q_prev || !tmp ||
      !fr) {
    free(tmp), free(fr);
    csf_romActuatorDestroy(ra);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom_act: out of memory");
  }
  /* the reduced tip force per unit force: V^T (tip_unit e_i) */
  for (int i = 0; i < 3; i++) {
    for (size_t k = 0; k < nd; k++) {
      tmp[k] = (int)(k % 3) == i ? ra->fe.tip_unit[k] : 0.0;
    }
    csf_romProject(ra->rom, tmp, fr);
    for (int j = 0; j < n; j++) {
      ra->Ftip[3 * j + i] = fr[j];
    }
  }
  free(tmp), free(fr);
  return CS_OK;
}

csStatus csf_romActuatorFromModel(const csrActuator* act, const csfActuatorSpec* spec,
                                  csfMesh* mesh, csfModel* model, csfRom* rom,
                                  const char* source, csfRomActuator* ra, csError* err) {
  memset(ra, 0, sizeof *ra);
  snprintf(ra->basis_path, sizeof ra->basis_path, "%s", source ? source : "");
  ra->rom = rom;
  if (!rom || rom->fem != model) {
    csf_romActuatorDestroy(ra);
    csf_modelDestroy(model);
    csf_meshDestroy(mesh);
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom_act: the reduced model is not on this FE model");
  }
  if (rom->nch != CSR_NSEG * CSR_NCHAMBER) {
    csf_romActuatorDestroy(ra);
    csf_modelDestroy(model);
    csf_meshDestroy(mesh);
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom_act: %s: the reduced model has %d chambers in "
                       "closed form, not %d", source ? source : "", rom->nch,
                       CSR_NSEG * CSR_NCHAMBER);
  }
  csStatus st = csf_actuatorFEFromModel(act, spec, mesh, model, &ra->fe, err);
  if (st != CS_OK) {
    csf_romActuatorDestroy(ra);
    return st;
  }
  return finish(ra, err);
}

csStatus csf_romActuatorSetWeights(csfRomActuator* ra, const char* weights_path, csError* err) {
  return readWeights(ra, weights_path, err);
}

void csf_romActuatorDestroy(csfRomActuator* ra) {
  csf_romDataDestroy(ra->d);
  csf_romDestroy(ra->rom);
  csf_actuatorFEDestroy(&ra->fe);
  free(ra->face_p), free(ra->Ftip), free(ra->f_dead), free(ra->u), free(ra->q_conv);
  free(ra->q_prev);
  ra->d = NULL, ra->rom = NULL, ra->face_p = ra->Ftip = ra->f_dead = ra->u = ra->q_conv = NULL;
  ra->q_prev = NULL;
}

/* the loads at ramp parameter s in [0, 1] between the start (p0, g0, F0) and the target */
static void setLoad(csfRomActuator* ra, double s, const double* p,
                    const double g[3], const double F[3], csfRomLoad* ld) {
  const csfMesh* me = ra->fe.mesh;
  for (int f = 0; f < me->nface; f++) {
    const int tag = me->face_tag[f], seg = tag / 10 - 11, j = tag % 10 - 1;
    ra->face_p[f] = 0.0;
    if (tag >= CSF_TAG_CHAMBER(0, 1) && seg >= 0 && seg < CSR_NSEG && j >= 0 &&
        j < CSR_NCHAMBER) {
      ra->face_p[f] = (1 - s) * ra->p0[seg][j] + s * p[CSR_NCHAMBER * seg + j];
    }
  }
  double Fs[3];
  for (int i = 0; i < 3; i++) {
    ld->gravity[i] = (1 - s) * ra->g0[i] + s * g[i];
    Fs[i] = (1 - s) * ra->F0[i] + s * F[i];
  }
  for (int j = 0; j < ra->rom->n; j++) {
    ra->f_dead[j] = ra->Ftip[3 * j] * Fs[0] + ra->Ftip[3 * j + 1] * Fs[1] +
                    ra->Ftip[3 * j + 2] * Fs[2];
  }
  ld->face_p = ra->face_p;
  ld->f_dead = ra->f_dead;
}

/* the load as one vector for the predictor's line test (fem_rom_act.h csfRomActuator.L_conv) */
static void loadVector(const double* p, const double g[3], const double F[3], double L[18]) {
  memcpy(L, p, 12 * sizeof(double));
  for (int i = 0; i < 3; i++) {
    L[12 + i] = 1e-4 * g[i], L[15 + i] = F[i];
  }
}

/* the start of the next Newton solve at load Lt: the secant q_conv + lambda (q_conv - q_prev)
 * when Lt - L_conv = lambda (L_conv - L_prev), lambda > 0 (to round-off), else q_conv. Only the
 * start moves: the residual decides the solution, and the element states (the tangent's) stay
 * those of q_conv, as after a converged step. */
static void predict(csfRomActuator* ra, const double Lt[18]) {
  const int n = ra->rom->n;
  memcpy(ra->d->q, ra->q_conv, (size_t)n * sizeof(double));
  if (ra->nhist < 2) {
    return;
  }
  double a[18], b[18], ab = 0, bb = 0, aa = 0;
  for (int i = 0; i < 18; i++) {
    a[i] = Lt[i] - ra->L_conv[i], b[i] = ra->L_conv[i] - ra->L_prev[i];
    ab += a[i] * b[i], bb += b[i] * b[i], aa += a[i] * a[i];
  }
  if (!(bb > 0) || !(ab > 0)) {
    return;
  }
  const double lambda = ab / bb;
  double off = 0;
  for (int i = 0; i < 18; i++) {
    off += (a[i] - lambda * b[i]) * (a[i] - lambda * b[i]);
  }
  if (off > 1e-18 * aa) {
    return; /* not along the last step's line */
  }
  const double l = fmin(lambda, 2.0); /* no farther than twice the last step */
  for (int j = 0; j < n; j++) {
    ra->d->q[j] = ra->q_conv[j] + l * (ra->q_conv[j] - ra->q_prev[j]);
  }
}

csStatus csf_romActuatorSolve(csfRomActuator* ra, const double* p,
                              const double g[3], const double F[3], csError* err) {
  /* no load: the reference state, as the FE's p = 0 row (the smoothed tension-only fibres carry
   * a small force at zero strain, which neither model equilibrates at rest) */
  int loaded = g[0] != 0 || g[1] != 0 || g[2] != 0 || F[0] != 0 || F[1] != 0 || F[2] != 0;
  for (int k = 0; k < CSR_NSEG * CSR_NCHAMBER; k++) {
    loaded |= p[k] != 0;
  }
  if (!loaded) {
    csf_romDataReset(ra->rom, ra->d);
    memset(ra->q_conv, 0, (size_t)ra->rom->n * sizeof(double));
    memset(ra->p, 0, sizeof ra->p);
    memset(ra->gravity, 0, sizeof ra->gravity);
    memset(ra->tip_force, 0, sizeof ra->tip_force);
    csf_romExpand(ra->rom, ra->d->q, ra->u);
    return CS_OK;
  }
  memcpy(ra->p0, ra->p, sizeof ra->p0);
  memcpy(ra->g0, ra->gravity, sizeof ra->g0);
  memcpy(ra->F0, ra->tip_force, sizeof ra->F0);
  const size_t n = (size_t)ra->rom->n;
  /* the predictor's history holds only if the caller left the last solved state in place (the
   * callers reset q and the load to start a new path) */
  double L0[18];
  loadVector(&ra->p[0][0], ra->gravity, ra->tip_force, L0);
  if (ra->nhist == 0 || memcmp(L0, ra->L_conv, sizeof L0) != 0 ||
      memcmp(ra->d->q, ra->q_conv, n * sizeof(double)) != 0) {
    memcpy(ra->q_conv, ra->d->q, n * sizeof(double));
    memcpy(ra->L_conv, L0, sizeof L0);
    ra->nhist = 1;
  }
  csfRomNewtonOptions o = csf_romNewtonDefault();
  o.rtol = ra->rtol;
  o.k_lag = ra->k_lag;
  o.bfgs = ra->bfgs;
  o.bfgs_keep = ra->bfgs_keep;
  double s = 0.0, ds = 1.0;
  csError lerr;
  cs_errorClear(&lerr);
  while (s < 1.0) {
    const double sn = fmin(1.0, s + ds);
    csfRomLoad ld;
    setLoad(ra, sn, p, g, F, &ld);
    double Lt[18], ps[12], Fs[3];
    for (int k = 0; k < 12; k++) {
      ps[k] = (1 - sn) * (&ra->p0[0][0])[k] + sn * p[k];
    }
    for (int i = 0; i < 3; i++) {
      Fs[i] = (1 - sn) * ra->F0[i] + sn * F[i];
    }
    loadVector(ps, ld.gravity, Fs, Lt);
    predict(ra, Lt);
    int it = 0;
    if (csf_romNewton(ra->rom, ra->d, &ld, &o, &it, &lerr) == CS_OK) {
      s = sn;
      ra->n_steps++;
      ra->n_newton += it;
      memcpy(ra->q_prev, ra->q_conv, n * sizeof(double));
      memcpy(ra->L_prev, ra->L_conv, sizeof Lt);
      memcpy(ra->q_conv, ra->d->q, n * sizeof(double));
      memcpy(ra->L_conv, Lt, sizeof Lt);
      ra->nhist = ra->nhist < 2 ? ra->nhist + 1 : 2;
      ds = it <= RAMP_GROW_ITERS ? 1.5 * ds : ds;
    } else {
      ra->n_cutbacks++;
      memcpy(ra->d->q, ra->q_conv, n * sizeof(double));
      if ((ds *= 0.5) < RAMP_MIN_REL) {
        /* keep the last solved state and its load */
        for (int seg = 0; seg < CSR_NSEG; seg++) {
          for (int j = 0; j < CSR_NCHAMBER; j++) {
            ra->p[seg][j] = (1 - s) * ra->p0[seg][j] + s * p[CSR_NCHAMBER * seg + j];
          }
        }
        for (int i = 0; i < 3; i++) {
          ra->gravity[i] = (1 - s) * ra->g0[i] + s * g[i];
          ra->tip_force[i] = (1 - s) * ra->F0[i] + s * F[i];
        }
        csf_romExpand(ra->rom, ra->d->q, ra->u);
        return cs_errorSet(err, CS_ERR_DIVERGED, "fem_rom: no reduced equilibrium beyond %.4g of "
                           "the load step: %.300s", s, lerr.msg);
      }
    }
  }
  memcpy(&ra->p[0][0], p, sizeof ra->p);
  memcpy(ra->gravity, g, sizeof ra->gravity);
  memcpy(ra->tip_force, F, sizeof ra->tip_force);
  csf_romExpand(ra->rom, ra->d->q, ra->u);
  return CS_OK;
}

void csf_romActuatorLoad(csfRomActuator* ra, const double* p, const double g[3],
                         const double F[3], csfRomLoad* ld) {
  memset(ra->p0, 0, sizeof ra->p0);
  memset(ra->g0, 0, sizeof ra->g0);
  memset(ra->F0, 0, sizeof ra->F0);
  setLoad(ra, 1.0, p, g, F, ld);
}

csStatus csf_romBasisReadTraining(const char* basis_path, int n, int* ns, double** q, double** p,
                                  double** g, double** F, csError* err) {
  *q = *p = *g = *F = NULL;
  *ns = 0;
  csStatus st = CS_OK;
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(basis_path, H5F_ACC_RDONLY, H5P_DEFAULT);
    size_t nq = 0, np = 0, ng = 0, nf = 0;
    if (f >= 0) {
      *q = readDoubles(f, "q_snap", 0, &nq);
      *p = readDoubles(f, "p_snap", 0, &np);
      *g = readDoubles(f, "g_snap", 0, &ng);
      *F = readDoubles(f, "F_snap", 0, &nf);
      H5Fclose(f);
    }
    const size_t m = nq / (size_t)n;
    if (f < 0 || !*q || !*p || !*g || !*F || m * (size_t)n != nq || np != 12 * m || ng != 3 * m ||
        nf != 3 * m) {
      free(*q), free(*p), free(*g), free(*F);
      *q = *p = *g = *F = NULL;
      st = cs_errorSet(err, CS_ERR_IO, "%s: no training snapshots (q_snap [ns, %d], p_snap [ns, "
                       "3, 4], g_snap, F_snap [ns, 3])", basis_path, n);
    } else {
      *ns = (int)m;
    }
  }
  H5E_END_TRY;
  return st;
}

csfData csf_romActuatorView(const csfRomActuator* ra) {
  csfData v;
  memset(&v, 0, sizeof v);
  v.ndof = ra->fe.model->ndof;
  v.u = ra->u;
  return v;
}
