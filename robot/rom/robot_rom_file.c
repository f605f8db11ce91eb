/* robot_rom_file.c: the rom leg's file read back (robot_rom_file.h).
 *
 * Rationale: the reduced model needs the FE model's reference geometry, fibres, clamp and faces,
 * never its solver or mesher; everything the actuator's FE set-up (fem_actuator.c, gmsh) and
 * csf_romChamberTensors (n + 1 passes over the chambers' faces: the set-up's dominant cost at
 * n = 96) computed is in the file, so the run builds the csfModel from arrays
 * (csf_modelCreate, the fibre arrays, csf_modelFinalize) and fills the csfRom's chamber forms
 * as csf_romChamberTensors leaves them (fem_rom.h documents the fields; csf_romDestroy frees
 * them). */
#include "robot_rom_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_h5.h"
#include "core_h5read.h"
#include "fem_assembly.h"
#include "fem_model.h"

/* a dataset as ints, each checked in [lo, hi); NULL and err otherwise */
static int* readInts(const csH5Reader* r, const char* path, const char* name, int rank,
                     const size_t* want, size_t* count, int lo, int hi, csError* err) {
  size_t dims[4] = {1, 1, 1, 1};
  double* d = cs_h5ReaderDoubles(r, name, rank, want, dims, NULL, err);
  if (!d) {
    return NULL;
  }
  const size_t n = dims[0] * dims[1] * dims[2] * dims[3];
  int* v = malloc((n ? n : 1) * sizeof(int));
  if (!v) {
    free(d);
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory for %s", path, name);
    return NULL;
  }
  for (size_t i = 0; i < n; i++) {
    if (!(d[i] >= lo && d[i] < hi) || d[i] != floor(d[i])) {
      cs_errorSet(err, CS_ERR_IO, "%s: %s[%zu] = %g is not an index in %d..%d", path, name, i,
                  d[i], lo, hi - 1);
      free(d), free(v);
      return NULL;
    }
    v[i] = (int)d[i];
  }
  free(d);
  if (count) {
    *count = n;
  }
  return v;
}

/* a dataset of finite doubles of the given shape */
static double* readFinite(const csH5Reader* r, const char* path, const char* name, int rank,
                          const size_t* want, csError* err) {
  size_t dims[4] = {1, 1, 1, 1};
  double* d = cs_h5ReaderDoubles(r, name, rank, want, dims, NULL, err);
  if (!d) {
    return NULL;
  }
  const size_t n = dims[0] * dims[1] * dims[2] * dims[3];
  for (size_t i = 0; i < n; i++) {
    if (!isfinite(d[i])) {
      cs_errorSet(err, CS_ERR_IO, "%s: %s[%zu] is not finite", path, name, i);
      free(d);
      return NULL;
    }
  }
  return d;
}

void csr_romLegFileFree(csrRomLegFile* lf) {
  if (!lf) {
    return;
  }
  csf_romDestroy(lf->rom);
  csf_modelDestroy(lf->model);
  csf_meshDestroy(lf->mesh);
  free(lf->sole);
  memset(lf, 0, sizeof *lf);
}

csStatus csr_romLegFileRead(const char* path, csrRomLegFile* lf, csError* err) {
  memset(lf, 0, sizeof *lf);
  csH5Reader* r = cs_h5ReaderOpen(path, err);
  if (!r) {
    return err->status;
  }
  char fmt[64] = "";
  if (cs_h5ReaderAttrString(r, "format", fmt, sizeof fmt, NULL) != CS_OK ||
      strcmp(fmt, CSR_ROM_FILE_FORMAT) != 0) {
    cs_h5ReaderClose(r);
    return cs_errorSet(err, CS_ERR_IO, "%s: not a rom leg file (format \"%s\", expected \"%s\": "
                       "make one with crawlsim rom leg-file)", path, fmt, CSR_ROM_FILE_FORMAT);
  }
  char status[32] = "";
  cs_h5ReaderAttrString(r, "status", status, sizeof status, NULL);
  if (strcmp(status, "complete") != 0) {
    cs_h5ReaderClose(r);
    return cs_errorSet(err, CS_ERR_IO, "%s: the leg file is incomplete (status \"%s\")", path,
                       status);
  }
  double a_n = 0, a_m = 0, C10 = 0, C20 = 0, kappa = 0, kappa_pt = 0, rho = 0, form = 0,
         fto = 1, fgt = 0, fsp = 1;
  csStatus st = CS_OK;
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "n", &a_n, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "m", &a_m, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "C10", &C10, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "C20", &C20, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "kappa", &kappa, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "kappa_pt", &kappa_pt, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "rho", &rho, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "form", &form, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "fib_tension_only", &fto, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "fib_geo_tension", &fgt, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "fib_split", &fsp, err);
  if (st == CS_OK) st = cs_h5ReaderAttrDouble(r, "fe_mesh_size_mm", &lf->l_soft, err);
  if (st == CS_OK) {
    st = cs_h5ReaderAttrString(r, "actuator_names", lf->act_names, sizeof lf->act_names, err);
  }
  if (st != CS_OK) {
    cs_h5ReaderClose(r);
    return st;
  }
  cs_h5ReaderAttrString(r, "basis", lf->basis, sizeof lf->basis, NULL);
  cs_h5ReaderAttrString(r, "weights", lf->weights, sizeof lf->weights, NULL);
  const int n = (int)a_n, m = (int)a_m;
  if (n < 1 || n > 4096 || a_n != n || m < 0 || m > 4096 || a_m != m || !(C10 > 0) ||
      !(kappa > 0) || !(rho > 0) || (form != CSF_FORM_MIXED_P0 && form != CSF_FORM_DISPLACEMENT)) {
    cs_h5ReaderClose(r);
    return cs_errorSet(err, CS_ERR_IO, "%s: bad attributes (n %g, m %g, C10 %g, kappa %g, rho %g, "
                       "form %g)", path, a_n, a_m, C10, kappa, rho, form);
  }
  /* the mesh */
  csfMesh* me = calloc(1, sizeof *me);
  lf->mesh = me;
  size_t dims[4] = {0, 0, 0, 0};
  size_t w3[2] = {0, 3};
  if (!me) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  } else if (!(me->x = cs_h5ReaderDoubles(r, "/mesh/x", 2, w3, dims, NULL, err))) {
    st = err->status;
  }
  if (st == CS_OK) {
    me->nnode = (int)dims[0];
    for (size_t i = 0; i < 3 * dims[0]; i++) {
      if (!isfinite(me->x[i])) {
        st = cs_errorSet(err, CS_ERR_IO, "%s: /mesh/x[%zu] is not finite", path, i);
        break;
      }
    }
  }
  size_t cnt = 0;
  const size_t w10[2] = {0, 10}, w6[2] = {0, 6};
  if (st == CS_OK &&
      !(me->tet = readInts(r, path, "/mesh/tet", 2, w10, &cnt, 0, me->nnode, err))) {
    st = err->status;
  }
  if (st == CS_OK) {
    me->ntet = (int)(cnt / 10);
    if (!(me->face = readInts(r, path, "/mesh/face", 2, w6, &cnt, 0, me->nnode, err))) {
      st = err->status;
    }
  }
  if (st == CS_OK) {
    me->nface = (int)(cnt / 6);
    const size_t wf[1] = {(size_t)me->nface};
    if (!(me->face_tet = readInts(r, path, "/mesh/face_tet", 1, wf, NULL, 0, me->ntet, err)) ||
        !(me->face_tag = readInts(r, path, "/mesh/face_tag", 1, wf, NULL, 0, 1 << 20, err))) {
      st = err->status;
    }
  }
  /* the FE model of the kernels: the material, the clamp, the fibres, the pattern */
  if (st == CS_OK) {
    csfMaterial mat = csf_materialDefault(C10, C20, rho);
    mat.kappa = kappa, mat.kappa_pt = kappa_pt, mat.form = (csfFormulation)form;
    lf->model = csf_modelCreate(me, &mat, err);
    st = lf->model ? CS_OK : err->status;
  }
  csfModel* fm = lf->model;
  if (st == CS_OK) {
    const size_t wd[1] = {(size_t)fm->ndof};
    int* fixed = readInts(r, path, "/mesh/fixed", 1, wd, NULL, 0, 2, err);
    if (!fixed) {
      st = err->status;
    } else {
      for (int k = 0; k < fm->ndof; k++) {
        fm->fixed[k] = (unsigned char)fixed[k];
      }
      free(fixed);
    }
  }
  if (st == CS_OK && cs_h5ReaderHas(r, "/fibre/node")) {
    const size_t w20[2] = {0, 20};
    fm->fib_node = readInts(r, path, "/fibre/node", 2, w20, &cnt, 0, me->nnode, err);
    if (!fm->fib_node) {
      st = err->status;
    } else {
      fm->nfib = (int)(cnt / 20);
      const size_t wc[2] = {(size_t)fm->nfib, 20}, wl[1] = {(size_t)fm->nfib};
      if (!(fm->fib_coef = readFinite(r, path, "/fibre/coef", 2, wc, err)) ||
          !(fm->fib_L0 = readFinite(r, path, "/fibre/L0", 1, wl, err)) ||
          !(fm->fib_EA = readFinite(r, path, "/fibre/EA", 1, wl, err))) {
        st = err->status;
      }
      for (int e = 0; st == CS_OK && e < fm->nfib; e++) {
        if (!(fm->fib_L0[e] > 0) || !(fm->fib_EA[e] >= 0)) {
          st = cs_errorSet(err, CS_ERR_IO, "%s: fibre element %d has L0 %g mm, EA %g N", path, e,
                           fm->fib_L0[e], fm->fib_EA[e]);
        }
      }
    }
    fm->fib_tension_only = fto != 0;
    fm->fib_geo_tension = fgt != 0;
    fm->fib_split = fsp != 0;
  }
  if (st == CS_OK) {
    st = csf_modelFinalizeKernels(fm, err); /* the rom never assembles: no sparse pattern */
  }
  /* the reduced model */
  double* V = NULL;
  if (st == CS_OK) {
    const size_t wv[2] = {(size_t)fm->ndof, (size_t)n};
    V = readFinite(r, path, "/V", 2, wv, err);
    st = V ? CS_OK : err->status;
  }
  if (st == CS_OK) {
    lf->rom = csf_romCreate(fm, n, V, err);
    st = lf->rom ? CS_OK : err->status;
  }
  free(V);
  if (st == CS_OK && m > 0) {
    const size_t wp[2] = {(size_t)me->ntet, (size_t)m};
    double* P = readFinite(r, path, "/P", 2, wp, err);
    st = P ? csf_romSetPressureBasis(lf->rom, m, P, err) : err->status;
    free(P);
  }
  static const char* const kId[CSF_ROM_NSET] = {"/weights/tet_id", "/weights/fibre_id",
                                                "/weights/face_id"};
  static const char* const kW[CSF_ROM_NSET] = {"/weights/tet_w", "/weights/fibre_w",
                                               "/weights/face_w"};
  const int nel[CSF_ROM_NSET] = {me ? me->ntet : 0, fm ? fm->nfib : 0, me ? me->nface : 0};
  for (int s = 0; st == CS_OK && s < CSF_ROM_NSET; s++) {
    size_t ne = 0;
    int* id = readInts(r, path, kId[s], 1, NULL, &ne, 0, nel[s] > 0 ? nel[s] : 1, err);
    const size_t wn[1] = {ne};
    double* w = id ? readFinite(r, path, kW[s], 1, wn, err) : NULL;
    st = w ? csf_romSetWeights(lf->rom, (csfRomSet)s, (int)ne, id, w, err) : err->status;
    free(id), free(w);
  }
  /* the mixed fibre field (absent: the FE's fibres), factored over the kept fibres */
  if (st == CS_OK && cs_h5ReaderHas(r, "/Qf")) {
    size_t dq[4] = {0, 0, 0, 0};
    const size_t wq[2] = {(size_t)fm->nfib, 0};
    double* Q = cs_h5ReaderDoubles(r, "/Qf", 2, wq, dq, NULL, err);
    st = Q ? csf_romSetFibreBasis(lf->rom, (int)dq[1], Q, err) : err->status;
    if (st != CS_OK && Q) {
      /* a one-line cause naming the file (not finite, or a mode without kept fibres) */
      char why[sizeof err->msg];
      snprintf(why, sizeof why, "%s", err->msg);
      st = cs_errorSet(err, CS_ERR_IO, "%s: /Qf: %s", path, why);
    }
    free(Q);
  }
  /* the chambers' cubic forms, as csf_romChamberTensors leaves them */
  if (st == CS_OK) {
    const int nch = 12;
    const size_t wf[1] = {(size_t)me->nface}, w1[1] = {(size_t)nch},
                 wg[2] = {(size_t)nch, (size_t)n},
                 wh[4] = {(size_t)nch, (size_t)n + 1, (size_t)n, (size_t)n};
    csfRom* rom = lf->rom;
    free(rom->face_ch), free(rom->ch_V0), free(rom->ch_g0), free(rom->ch_H);
    rom->face_ch = NULL, rom->ch_V0 = rom->ch_g0 = rom->ch_H = NULL;
    rom->nch = 0;
    if (!(rom->face_ch = readInts(r, path, "/chambers/face_ch", 1, wf, NULL, -1, nch, err)) ||
        !(rom->ch_V0 = readFinite(r, path, "/chambers/V0", 1, w1, err)) ||
        !(rom->ch_g0 = readFinite(r, path, "/chambers/g0", 2, wg, err)) ||
        !(rom->ch_H = readFinite(r, path, "/chambers/H", 4, wh, err))) {
      st = err->status;
    } else {
      rom->nch = nch;
    }
  }
  if (st == CS_OK) {
    size_t ns = 0;
    lf->sole = readInts(r, path, "/sole", 1, NULL, &ns, 0, me->nnode, err);
    st = lf->sole ? CS_OK : err->status;
    lf->nsole = (int)ns;
  }
  if (st == CS_OK) {
    size_t na = 0;
    double* a = cs_h5ReaderDoubles(r, "/actuator", 1, NULL, &na, NULL, err);
    if (!a || na > CSR_ROM_FILE_MAXACT) {
      st = a ? cs_errorSet(err, CS_ERR_IO, "%s: /actuator has %zu values", path, na)
             : err->status;
    } else {
      memcpy(lf->act, a, na * sizeof(double));
      lf->nact = (int)na;
    }
    free(a);
  }
  if (st == CS_OK) {
    double vol = 0;
    for (int e = 0; e < me->ntet; e++) {
      vol += fm->vol[e];
    }
    lf->mass = rho * vol;
  }
  cs_h5ReaderClose(r);
  if (st != CS_OK) {
    csr_romLegFileFree(lf);
  }
  return st;
}

typedef struct SigCheck_ {
  const csrRomLegFile* lf;
  int k;
  char bad[160];
} SigCheck;

static void checkParam(void* user, const char* name, double value) {
  SigCheck* c = user;
  const int k = c->k++;
  if (c->bad[0]) {
    return;
  }
  if (k >= c->lf->nact) {
    snprintf(c->bad, sizeof c->bad, "it has no value of %s", name);
    return;
  }
  const double f = c->lf->act[k];
  if (fabs(f - value) > 1e-9 * fmax(fabs(f), fabs(value))) {
    snprintf(c->bad, sizeof c->bad, "%s is %.10g there, %.10g in this run's legs", name, f,
             value);
  }
}

csStatus csr_romLegFileCheckActuator(const csrRomLegFile* lf, const char* path,
                                     const csrActuator* act, csError* err) {
  /* the names must be the same list in the same order (the file's own record of it) */
  char names[CSR_ROM_FILE_NAMES] = "";
  for (int i = 0; csr_actuator_param_names[i]; i++) {
    snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? "," : "",
             csr_actuator_param_names[i]);
  }
  if (strcmp(names, lf->act_names) != 0) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: the leg file names the actuator's parameters "
                       "\"%.100s\", this build \"%.100s\": remake it with crawlsim rom leg-file",
                       path, lf->act_names, names);
  }
  SigCheck c = {lf, 0, ""};
  csr_actuatorVisit(act, checkParam, &c);
  if (c.bad[0]) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: the leg file was built for another actuator: %s "
                       "(--set the legs as the file's, or make a leg file for these)", path,
                       c.bad);
  }
  return CS_OK;
}


/* an int array as doubles (HDF5 stores what the writer has: doubles) */
static csStatus writeInts(csH5File* f, const char* path, int rank, const size_t* dims,
                          const int* v, csError* err) {
  size_t cnt = 1;
  for (int k = 0; k < rank; k++) {
    cnt *= dims[k];
  }
  double* d = malloc((cnt ? cnt : 1) * sizeof(double));
  if (!d) {
    return cs_errorSet(err, CS_ERR_MEMORY, "out of memory (%zu values)", cnt);
  }
  for (size_t i = 0; i < cnt; i++) {
    d[i] = v[i];
  }
  const csStatus st = cs_h5WriteDoubles(f, path, rank, dims, d, err);
  free(d);
  return st;
}

typedef struct ActSig_ {
  char names[CSR_ROM_FILE_NAMES];
  double v[64];
  int n;
} ActSig;

static void visitSig(void* user, const char* name, double value) {
  ActSig* s = user;
  if (s->n < 64) {
    snprintf(s->names + strlen(s->names), sizeof s->names - strlen(s->names), "%s%s",
             s->n ? "," : "", name);
    s->v[s->n++] = value;
  }
}

csStatus csr_romLegFileWrite(const char* out, const csfRom* rom, int nsole, const int* sole_nodes,
                             const csrActuator* act, double l_soft, const char* basis,
                             const char* weights, csError* err) {
  const csfModel* fm = rom->fem;
  const csfMesh* me = fm->mesh;
  const size_t n = (size_t)rom->n, nd = (size_t)fm->ndof;
  csH5File* f = cs_h5Create(out, err);
  if (!f) {
    return err->status;
  }
  if (rom->nch != 12) {
    cs_h5Close(f);
    return cs_errorSet(err, CS_ERR_ARG, "%s: the reduced model has %d chambers in closed form, "
                       "not 12 (csf_romChamberTensors)", out, rom->nch);
  }
  csStatus st = CS_OK;
  {
    const size_t dx[2] = {(size_t)me->nnode, 3}, dt[2] = {(size_t)me->ntet, 10},
                 df[2] = {(size_t)me->nface, 6}, d1[1] = {(size_t)me->nface};
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/mesh/x", 2, dx, me->x, err);
    if (st == CS_OK) st = writeInts(f, "/mesh/tet", 2, dt, me->tet, err);
    if (st == CS_OK) st = writeInts(f, "/mesh/face", 2, df, me->face, err);
    if (st == CS_OK) st = writeInts(f, "/mesh/face_tet", 1, d1, me->face_tet, err);
    if (st == CS_OK) st = writeInts(f, "/mesh/face_tag", 1, d1, me->face_tag, err);
  }
  /* the clamp: the fixed dofs */
  int* fixed = malloc(nd * sizeof(int));
  if (!fixed) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
  }
  if (st == CS_OK) {
    for (size_t k = 0; k < nd; k++) {
      fixed[k] = fm->fixed[k];
    }
    st = writeInts(f, "/mesh/fixed", 1, &nd, fixed, err);
  }
  free(fixed);
  if (fm->nfib > 0) {
    const size_t d20[2] = {(size_t)fm->nfib, 20}, d1[1] = {(size_t)fm->nfib};
    if (st == CS_OK) st = writeInts(f, "/fibre/node", 2, d20, fm->fib_node, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/fibre/coef", 2, d20, fm->fib_coef, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/fibre/L0", 1, d1, fm->fib_L0, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/fibre/EA", 1, d1, fm->fib_EA, err);
  }
  {
    const size_t dv[2] = {nd, n};
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/V", 2, dv, rom->V, err);
  }
  if (rom->m > 0 && st == CS_OK) {
    const size_t dp[2] = {(size_t)me->ntet, (size_t)rom->m};
    st = cs_h5WriteDoubles(f, "/P", 2, dp, rom->P, err);
  }
  if (rom->mf > 0 && st == CS_OK) { /* the mixed fibre field's strain basis (csfRom.mf) */
    const size_t dq[2] = {(size_t)fm->nfib, (size_t)rom->mf};
    st = cs_h5WriteDoubles(f, "/Qf", 2, dq, rom->Qf, err);
  }
  /* the kept elements and their weights, every set (all of them at 1 without weights) */
  static const char* const kId[CSF_ROM_NSET] = {"/weights/tet_id", "/weights/fibre_id",
                                                "/weights/face_id"};
  static const char* const kW[CSF_ROM_NSET] = {"/weights/tet_w", "/weights/fibre_w",
                                               "/weights/face_w"};
  for (int s = 0; s < CSF_ROM_NSET && st == CS_OK; s++) {
    const size_t ne = (size_t)rom->nel[s];
    st = writeInts(f, kId[s], 1, &ne, rom->el[s], err);
    if (st == CS_OK) {
      st = cs_h5WriteDoubles(f, kW[s], 1, &ne, rom->w[s], err);
    }
  }
  /* the chambers' cubic forms (fem_rom.h csfRom.nch) */
  if (st == CS_OK) {
    const size_t nch = (size_t)rom->nch, d1[1] = {(size_t)me->nface}, dg[2] = {nch, n},
                 dh[4] = {nch, n + 1, n, n};
    st = writeInts(f, "/chambers/face_ch", 1, d1, rom->face_ch, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/chambers/V0", 1, &nch, rom->ch_V0, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/chambers/g0", 2, dg, rom->ch_g0, err);
    if (st == CS_OK) st = cs_h5WriteDoubles(f, "/chambers/H", 4, dh, rom->ch_H, err);
  }
  if (st == CS_OK) {
    const size_t ns = (size_t)nsole;
    st = writeInts(f, "/sole", 1, &ns, sole_nodes, err);
  }
  /* the actuator's parameters it was built for (the run's legs must match them) */
  ActSig sig = {"", {0}, 0};
  csr_actuatorVisit(act, visitSig, &sig);
  if (st == CS_OK) {
    const size_t na = (size_t)sig.n;
    st = cs_h5WriteDoubles(f, "/actuator", 1, &na, sig.v, err);
  }
  double mass = 0;
  for (int e = 0; e < me->ntet; e++) {
    mass += fm->vol[e];
  }
  mass *= fm->mat.rho;
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "format", CSR_ROM_FILE_FORMAT, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "actuator_names", sig.names, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "actuator_preset", act->name, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "basis", basis ? basis : "", err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "weights", weights ? weights : "", err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "n", (double)n, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "m", rom->m, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "mf", rom->mf, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_mesh_size_mm", l_soft, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "C10", fm->mat.C10, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "C20", fm->mat.C20, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "kappa", fm->mat.kappa, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "kappa_pt", fm->mat.kappa_pt, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "rho", fm->mat.rho, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "form", (double)fm->mat.form, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fib_tension_only", fm->fib_tension_only, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fib_geo_tension", fm->fib_geo_tension, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fib_split", fm->fib_split, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "mass_t", mass, err);
  if (st != CS_OK) {
    cs_h5AttrString(f, "/", "status", "failed", NULL);
    cs_h5Close(f);
    return st;
  }
  cs_h5AttrString(f, "/", "status", "complete", NULL);
  return cs_h5CloseChecked(f, err);
}

