/* test_calibration_synth.h: synthetic FE mode tables for the calibration tests (header-only,
 * test helper, not a unit).
 *
 * synthWrite writes a table in the layout of fem/fem_calibration.h (the format the lead's
 * calibration writer produces: root attributes, /cases/<name>/ with kind, ratio1..4, status,
 * p_end, p_limit and the per-row datasets, stiffness probes on O12 and O1234) from a known
 * "truth": a function of the four chamber pressures per segment, so that a test knows what the
 * model must return. The cases are the calibration's (names, kinds, chamber ratios, end
 * pressures). Optional: a spurious bend (the FE's mesh asymmetry) added to every row, so that
 * symmetry tests see the model remove it. The synth* mutators then break one thing in a
 * written file (a case dropped, an attribute changed, a dataset replaced) for the refusal
 * tests. */
#ifndef CS_TEST_CALIBRATION_SYNTH_H
#define CS_TEST_CALIBRATION_SYNTH_H

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_h5.h"
#include "cs_test.h"
#include "robot_actuator.h"
#include "robot_analytic.h"
#include "robot_calibration.h"

/* the truth of one segment under chamber pressures p[4]: bend (rad), stretch (-), radial (-),
 * largest radial growth (mm) */
typedef void (*SynthStateFn)(const void* ctx, int seg, const double p[4], double bend[2],
                             double* stretch, double* radial, double* radmax);
/* the truth of the stiffness at mean pressure pbar: EI (N mm^2) and EA (N) of segment seg */
typedef void (*SynthStiffFn)(const void* ctx, int seg, double pbar, double* EI, double* EA);

typedef struct {
  SynthStateFn state;
  SynthStiffFn stiff; /* NULL: no probes */
  const void* ctx;
  double dp;          /* MPa between rows */
  double p_cap;       /* MPa: every case ends at min(its end, p_cap); 0 = no cap */
  double asym;        /* rad/MPa: spurious bend (0.8 e1 + 0.6 e2) x p added to every row */
  int wrap;           /* 1: bends written as the FE measures them, rotation vectors of angle <=
                         pi (a bend theta > pi towards n as 2 pi - theta towards -n) */
} SynthSpec;

typedef struct {
  const char* name;
  const char* kind;
  double ratio[4];
  double p_max;
  int probes;
} SynthCase;

/* fem_calibration.c's cases (the gravity case G has no chamber pattern) */
static const SynthCase kSynthCases[] = {
    {"O12", "mode", {1, 1, 0, 0}, 0.5, 1},
    {"O1", "mode", {1, 0, 0, 0}, 0.5, 0},
    {"O124", "mode", {1, 1, 0, 1}, 0.5, 0},
    {"O1234", "mode", {1, 1, 1, 1}, 0.5, 1},
    {"O13", "mode", {1, 0, 1, 0}, 0.5, 0},
    {"O12r05", "mode", {1, 0.5, 0, 0}, 0.5, 0},
    {"O12O34r3", "mode", {1, 1, 1.0 / 3.0, 1.0 / 3.0}, 0.5, 0},
    {"O1O234r05", "mode", {1, 0.5, 0.5, 0.5}, 0.5, 0},
    {"O1O234r075", "mode", {1, 0.75, 0.75, 0.75}, 0.5, 0},
    {"O124O3r05", "mode", {1, 1, 0.5, 1}, 0.5, 0},
    {"O1O23r05O4r025", "mode", {1, 0.5, 0.5, 0.25}, 0.5, 0},
    {"O1O3r05", "mode", {1, 0, 0.5, 0}, 0.5, 0},
    {"O12O4r05", "mode", {1, 1, 0, 0.5}, 0.5, 0},
    {"O1O24r05", "mode", {1, 0.5, 0, 0.5}, 0.5, 0},
    {"O13O2r05", "mode", {1, 0.5, 1, 0}, 0.5, 0},
    {"O1O2r067O4r033", "mode", {1, 2.0 / 3.0, 0, 1.0 / 3.0}, 0.5, 0},
    {"O13O2r067O4r033", "mode", {1, 2.0 / 3.0, 1, 1.0 / 3.0}, 0.5, 0},
    {"O1O23r05", "mode", {1, 0.5, 0.5, 0}, 0.5, 0},
    {"O12O34r05", "mode", {1, 1, 0.5, 0.5}, 0.5, 0},
    {"O1O24r075O3r025", "mode", {1, 0.75, 0.25, 0.75}, 0.5, 0},
    {"O1O234r025", "mode", {1, 0.25, 0.25, 0.25}, 0.5, 0},
    {"O1O24r025O3r075", "mode", {1, 0.25, 0.75, 0.25}, 0.5, 0},
    {"O13O24r05", "mode", {1, 0.5, 1, 0.5}, 0.5, 0},
    {"O2", "symmetry", {0, 1, 0, 0}, 0.5, 0},
    {"H4t", "symmetry", {0.75, 1, 0.75, 0.375}, 0.4, 0},
    {"H6t", "symmetry", {0.4, 1, 0.8, 0.6}, 0.4, 0},
    {"H7t", "symmetry", {0.2, 1, 0.3, 0.7}, 0.4, 0},
    {"H1", "holdout", {1, 1.0 / 3.0, 0, 0}, 0.3, 0},
    {"H2", "holdout", {1, 1, 0.5, 0}, 0.2, 0},
    {"H3", "holdout", {1, 5.0 / 7.0, 5.0 / 7.0, 5.0 / 7.0}, 0.35, 0},
    {"H4", "holdout", {1, 0.75, 0.375, 0.75}, 0.4, 0},
    {"H5", "holdout", {1, 0.6, 0.3, 0.3}, 0.4, 0},
    {"H6", "holdout", {1, 0.8, 0.6, 0.4}, 0.4, 0},
    {"H7", "holdout", {1, 0.3, 0.7, 0.2}, 0.4, 0},
    {"H8", "holdout", {1, 1.0 / 3.0, 0, 0}, 0.4, 0},
    {"H9", "holdout", {1, 0.4, 0.8, 0.3}, 0.4, 0},
    {"H10", "holdout", {1, 0.625, 0.125, 0.625}, 0.4, 0},
    {"H11", "holdout", {1, 0.88, 0.04, 0.17}, 0.4, 0},
    {"H12", "holdout", {1, 0.27, 0.09, 0.9}, 0.4, 0},
    {"G", "gravity", {0, 0, 0, 0}, 0.025, 0},
};
#define SYNTH_NCASE ((int)(sizeof kSynthCases / sizeof kSynthCases[0]))

static const double kSynthProbeP[4] = {0.0, 0.1, 0.2, 0.3};

typedef struct {
  csH5File* h;
  csError* err;
} SynthAttr;

static inline void synthParam(void* user, const char* name, double value) {
  SynthAttr* w = user;
  CS_EXPECT(cs_h5AttrDouble(w->h, "/", name, value, w->err) == CS_OK);
}


/* write one case's group */
static inline void synthCase(csH5File* h, const csrActuator* act, const SynthSpec* sp,
                      const SynthCase* sc) {
  csError err;
  const double pmax = sp->p_cap > 0 ? fmin(sp->p_cap, sc->p_max) : sc->p_max;
  const int gravity = !strcmp(sc->kind, "gravity");
  const double dp = gravity ? pmax : sp->dp;
  const int m = (int)floor(pmax / dp + 1e-9) + 1;
  double* p = calloc((size_t)m, sizeof(double));
  double* bend = calloc((size_t)m * 6, sizeof(double));
  double* tw = calloc((size_t)m * 3, sizeof(double));
  double* st = calloc((size_t)m * 3, sizeof(double));
  double* ra = calloc((size_t)m * 3, sizeof(double));
  double* rm = calloc((size_t)m * 3, sizeof(double));
  double* tip = calloc((size_t)m * 3, sizeof(double));
  double* tot = calloc((size_t)m, sizeof(double));
  for (int i = 0; i < m; i++) {
    p[i] = i * dp;
    csrSegmentStrain ss[CSR_NSEG];
    memset(ss, 0, sizeof ss);
    for (int s = 0; s < CSR_NSEG; s++) {
      double P[4], b[2] = {0, 0}, l = 1, r = 0, x = 0;
      for (int j = 0; j < 4; j++) P[j] = gravity ? 0 : sc->ratio[j] * p[i];
      sp->state(sp->ctx, s, P, b, &l, &r, &x);
      b[0] += 0.8 * sp->asym * p[i];
      b[1] += 0.6 * sp->asym * p[i];
      bend[6 * i + 2 * s] = b[0], bend[6 * i + 2 * s + 1] = b[1];
      const double th = hypot(b[0], b[1]);
      if (sp->wrap && th > CS_PI) {
        bend[6 * i + 2 * s] *= 1 - 2 * CS_PI / th;
        bend[6 * i + 2 * s + 1] *= 1 - 2 * CS_PI / th;
      }
      st[3 * i + s] = l, ra[3 * i + s] = r, rm[3 * i + s] = x;
      ss[s].lambda0 = l;
      ss[s].kappa[0] = -b[0] / act->S[s], ss[s].kappa[1] = -b[1] / act->S[s];
      tot[i] += hypot(b[0], b[1]) / CS_DEG;
    }
    CS_EXPECT(csr_ccForwardKinematics(act, ss, 1, NULL, tip + 3 * i, NULL, &err) == CS_OK);
  }
  char g[96], d[160];
  snprintf(g, sizeof g, "/cases/%s", sc->name);
  size_t d1[1] = {(size_t)m}, d2[2] = {(size_t)m, 3}, d3[3] = {(size_t)m, 3, 2};
#define SYNTH_W(NAME, RANK, DIMS, DATA)                                          \
  snprintf(d, sizeof d, "%s/%s", g, NAME);                                        \
  CS_EXPECT(cs_h5WriteDoubles(h, d, RANK, DIMS, DATA, &err) == CS_OK)
  SYNTH_W("pressure", 1, d1, p);
  SYNTH_W("bend", 3, d3, bend);
  SYNTH_W("twist", 2, d2, tw);
  SYNTH_W("stretch", 2, d2, st);
  SYNTH_W("radial", 2, d2, ra);
  SYNTH_W("radial_max", 2, d2, rm);
  SYNTH_W("tip", 2, d2, tip);
  SYNTH_W("angle_total_deg", 1, d1, tot);
  if (sc->probes && sp->stiff) {
    int K = 0;
    for (int k = 0; k < 4; k++) K += kSynthProbeP[k] <= pmax + 1e-12;
    double pp[4], ei[24], ea[12], f3[12];
    double* pb = calloc((size_t)K * 18, sizeof(double));
    double* ps = calloc((size_t)K * 9, sizeof(double));
    for (int k = 0; k < K; k++) {
      pp[k] = kSynthProbeP[k];
      f3[3 * k] = f3[3 * k + 1] = 0.005, f3[3 * k + 2] = 0.05; /* the FE's default probes */
      const double rbar = 0.25 * (sc->ratio[0] + sc->ratio[1] + sc->ratio[2] + sc->ratio[3]);
      for (int s = 0; s < 3; s++) {
        double EI, EA;
        sp->stiff(sp->ctx, s, rbar * pp[k], &EI, &EA);
        ei[6 * k + 2 * s] = ei[6 * k + 2 * s + 1] = EI, ea[3 * k + s] = EA;
      }
    }
    size_t k1[1] = {(size_t)K}, k2[2] = {(size_t)K, 3}, kk3[3] = {(size_t)K, 3, 3},
           kk4[4] = {(size_t)K, 3, 3, 2}, kei[3] = {(size_t)K, 3, 2};
    SYNTH_W("probe_pressure", 1, k1, pp);
    SYNTH_W("probe_force", 2, k2, f3);
    SYNTH_W("probe_bend", 4, kk4, pb);
    SYNTH_W("probe_stretch", 3, kk3, ps);
    SYNTH_W("probe_tip", 3, kk3, ps);
    SYNTH_W("EI", 3, kei, ei);
    SYNTH_W("EA", 2, k2, ea);
    free(pb), free(ps);
  }
#undef SYNTH_W
  CS_EXPECT(cs_h5AttrString(h, g, "kind", sc->kind, &err) == CS_OK);
  for (int j = 0; j < 4; j++) {
    char nm[16];
    snprintf(nm, sizeof nm, "ratio%d", j + 1);
    CS_EXPECT(cs_h5AttrDouble(h, g, nm, sc->ratio[j], &err) == CS_OK);
  }
  CS_EXPECT(cs_h5AttrDouble(h, g, "p_end", p[m - 1], &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, g, "p_limit", NAN, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, g, "p_max", pmax, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrString(h, g, "status", "complete", &err) == CS_OK);
  free(p), free(bend), free(tw), free(st), free(ra), free(rm), free(tip), free(tot);
}


/* write the table at `path` for the actuator `act`: every case, or only the case `only` (a
 * case file of a resumable calibration, which `crawlsim calibrate` merges) */
static inline void synthWriteCases(const char* path, const csrActuator* act, const SynthSpec* sp,
                                   const char* only) {
  csError err;
  csH5File* h = cs_h5Create(path, &err);
  CS_EXPECT(h != NULL);
  if (!h) {
    return;
  }
  CS_EXPECT(cs_h5AttrString(h, "/", "format", "crawlsim-fe-calibration 1", &err) == CS_OK);
  SynthAttr w = {h, &err};
  csr_actuatorVisit(act, synthParam, &w);
  CS_EXPECT(cs_h5AttrString(h, "/", "actuator", act->name, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_mesh_size_mm", 4.0, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_fibre_size_mm", 0.5, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_fibre_split", 1.0, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrString(h, "/", "fe_fibre_law", "tension-only", &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_p_step_MPa", sp->dp, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_p_cap_MPa", sp->p_cap, &err) == CS_OK);
  /* the command's default Newton tolerance (csf_calibrationDefault), so the files count as done */
  CS_EXPECT(cs_h5AttrDouble(h, "/", "fe_newton_rtol", 1e-6, &err) == CS_OK);
  CS_EXPECT(cs_h5AttrString(h, "/", "fe_solver", "synthetic", &err) == CS_OK);
  CS_EXPECT(cs_h5AttrString(h, "/", "version", "test", &err) == CS_OK);
  for (int k = 0; k < SYNTH_NCASE; k++) {
    if (!only || !strcmp(only, kSynthCases[k].name)) {
      synthCase(h, act, sp, kSynthCases + k);
    }
  }
  cs_h5Close(h);
}


/* the whole table */
static inline void synthWrite(const char* path, const csrActuator* act, const SynthSpec* sp) {
  synthWriteCases(path, act, sp, NULL);
}


/* ---- mutators: one defect each ------------------------------------------------------------ */

static inline hid_t synthOpenRW(const char* path) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  return f;
}


static inline void synthDelete(const char* path, const char* obj) {
  hid_t f = synthOpenRW(path);
  CS_EXPECT(H5Ldelete(f, obj, H5P_DEFAULT) >= 0);
  H5Fclose(f);
}


static inline void synthDeleteAttr(const char* path, const char* obj, const char* name) {
  hid_t f = synthOpenRW(path);
  CS_EXPECT(H5Adelete_by_name(f, obj, name, H5P_DEFAULT) >= 0);
  H5Fclose(f);
}


static inline void synthSetString(const char* path, const char* obj, const char* name,
                           const char* value) {
  hid_t f = synthOpenRW(path);
  if (H5Aexists_by_name(f, obj, name, H5P_DEFAULT) > 0) {
    H5Adelete_by_name(f, obj, name, H5P_DEFAULT);
  }
  CS_EXPECT(H5LTset_attribute_string(f, obj, name, value) >= 0);
  H5Fclose(f);
}


/* a variable-length UTF-8 string attribute, as h5py writes a Python str */
static inline void synthSetVlenString(const char* path, const char* obj, const char* name,
                                      const char* value) {
  hid_t f = synthOpenRW(path);
  if (H5Aexists_by_name(f, obj, name, H5P_DEFAULT) > 0) {
    H5Adelete_by_name(f, obj, name, H5P_DEFAULT);
  }
  hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  hid_t a = H5Acreate_by_name(f, obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  CS_EXPECT(a >= 0 && H5Awrite(a, t, &value) >= 0);
  H5Aclose(a), H5Sclose(sp), H5Tclose(t);
  H5Fclose(f);
}


static inline void synthSetDouble(const char* path, const char* obj, const char* name,
                                  double value) {
  hid_t f = synthOpenRW(path);
  if (H5Aexists_by_name(f, obj, name, H5P_DEFAULT) > 0) {
    H5Adelete_by_name(f, obj, name, H5P_DEFAULT);
  }
  CS_EXPECT(H5LTset_attribute_double(f, obj, name, &value, 1) >= 0);
  H5Fclose(f);
}


/* read a dataset of doubles into a new array (n values), NULL if absent */
static inline double* synthRead(const char* path, const char* dset, hsize_t dims[4], int* rank) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  double* a = NULL;
  H5T_class_t cls;
  size_t sz;
  if (f >= 0 && H5LTget_dataset_ndims(f, dset, rank) >= 0 &&
      H5LTget_dataset_info(f, dset, dims, &cls, &sz) >= 0) {
    size_t n = 1;
    for (int i = 0; i < *rank; i++) n *= (size_t)dims[i];
    a = malloc(n * sizeof(double));
    if (a && H5LTread_dataset_double(f, dset, a) < 0) {
      free(a);
      a = NULL;
    }
  }
  if (f >= 0) {
    H5Fclose(f);
  }
  CS_EXPECT(a != NULL);
  return a;
}


/* replace a dataset by `data` with shape dims (rank) */
static inline void synthReplace(const char* path, const char* dset, int rank, const hsize_t* dims,
                         const double* data) {
  hid_t f = synthOpenRW(path);
  CS_EXPECT(H5Ldelete(f, dset, H5P_DEFAULT) >= 0);
  CS_EXPECT(H5LTmake_dataset_double(f, dset, rank, dims, data) >= 0);
  H5Fclose(f);
}


/* change one value (flat index) of a dataset */
static inline void synthPoke(const char* path, const char* dset, size_t index, double value) {
  hsize_t dims[4];
  int rank = 0;
  double* a = synthRead(path, dset, dims, &rank);
  if (a) {
    a[index] = value;
    synthReplace(path, dset, rank, dims, a);
    free(a);
  }
}


/* drop the last row of a dataset (a truncated write) */
static inline void synthTruncate(const char* path, const char* dset) {
  hsize_t dims[4];
  int rank = 0;
  double* a = synthRead(path, dset, dims, &rank);
  if (a) {
    dims[0]--;
    synthReplace(path, dset, rank, dims, a);
    free(a);
  }
}

/* opening `path` as a calibration for `leg` fails with one line naming the file and `want` */
static inline void expectRefused(const char* path, const csrActuator* leg, const char* want) {
  csError err;
  cs_errorClear(&err);
  csrCalibration* c = csr_calibrationOpen(path, leg, &err);
  int ok = c == NULL && strstr(err.msg, path) != NULL && strstr(err.msg, want) != NULL &&
           strchr(err.msg, '\n') == NULL;
  CS_EXPECT(ok);
  if (!ok) {
    fprintf(stderr, "  %s: got '%s', want '%s'\n", path, c ? "(opened)" : err.msg, want);
  }
  csr_calibrationClose(c);
}

#endif /* CS_TEST_CALIBRATION_SYNTH_H */
