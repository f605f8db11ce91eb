/* fuzz_calib_h5.c: structure-aware fuzz harness of the HDF5 calibration tables, opened the
 * way the legs open them: csr_calibrationOpen for the `leg` actuator (robot_calibration.h: the
 * FE mode table of robot_calibration_table.h, or the pair-mode table of the `crawlsim bend`
 * layout).
 *
 * Why structure-aware: HDF5's own parser is not ours and is not built to survive garbage bytes,
 * so the input never reaches it as bytes. It is an edit script instead: the first byte picks a
 * valid template table (an FE mode table with every case or only the five corner modes, a
 * 13-row or a 2-row pair-mode table); every further group of bytes is one edit of that table's
 * tree: delete a group, dataset or attribute; change an attribute's type (double, float,
 * integer, byte, fixed or variable-length string, long double), dataspace (null, scalar, rank
 * 1..4 of 0..3 elements), number or string; change a dataset's values, shape (ranks 0..5, zero
 * and huge extents, written or left as fill values), type or storage (contiguous, compact,
 * chunked, deflate); rename, duplicate or replace a node; add stray datasets, groups, soft,
 * hard and external links; write with the newest file format, a user block or dense
 * attributes. The edited tree is written through the HDF5 API into a file of this process,
 * then read. An empty input is the untouched mode table, so the fuzzer starts deep.
 *
 * Per input: the error contract (fuzz_common.h, "<file>: cause"); no HDF5 object left open by
 * the reader (H5Fget_obj_count, after a failure too); an accepted table gives a bend map that
 * evaluates in range and refuses above it, and a mode table a rod actuation that evaluates
 * (fuzz_calib_map.h). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "fuzz_calib_map.h"
#include "fuzz_common.h"
#include "robot_calibration.h"

/* ---- the tree of a table ------------------------------------------------------------------ */

enum { T_F64, T_F32, T_I32, T_U8, T_FSTR, T_VLSTR, T_LDBL, NTYPE };
enum { K_GROUP, K_DATASET, K_SOFT, K_HARD, K_EXTERNAL };
enum { L_CONTIGUOUS, L_COMPACT, L_CHUNKED, L_DEFLATE, L_SHUFFLE_DEFLATE, L_UNWRITTEN, NLAYOUT };

#define NAME_SIZE 96
#define PATH_SIZE 200
#define STR_SIZE 112
#define ATTR_NUM 4
#define MAX_RANK 5
/* elements a dataset may hold in memory; larger shapes are left unwritten (fill values) */
#define MAX_ELEMS 65536
/* nodes and attributes per node an edit script may grow a tree to */
#define MAX_NODES 400
#define MAX_ATTRS 48

typedef struct {
  char name[NAME_SIZE];
  int type;
  int rank; /* -1: null dataspace, 0: scalar, 1..4: simple */
  hsize_t dims[4];
  int pad;        /* strings: 0 NUL-terminated, 1 NUL-padded, 2 space-padded */
  size_t strsize; /* fixed strings: bytes (0 = len + 1) */
  double num[ATTR_NUM];
  int nnum;
  char str[STR_SIZE];
  size_t len;
} Attr;

typedef struct {
  char path[PATH_SIZE];
  int kind;
  char target[PATH_SIZE]; /* links */
  int type, rank, layout;
  hsize_t dims[MAX_RANK];
  double* data; /* (ndata) values, row-major; NULL when unwritten */
  size_t ndata;
  Attr* attr;
  int nattr;
} Node;

typedef struct {
  Node* node;
  int n;
  int libver_latest, userblock;
} Tree;

/* the templates, built once (test code: read-only after init) */
enum { TPL_MODE_FULL, TPL_MODE_CORNERS, TPL_PAIR, TPL_PAIR_SHORT, NTPL };
static Tree g_tpl[NTPL];
static csrActuator g_leg;


/* out = a + b (PATH_SIZE bytes, truncated) */
static void joinPath(char* out, const char* a, const char* b) {
  size_t na = strlen(a), nb = strlen(b);
  na = na < PATH_SIZE - 1 ? na : PATH_SIZE - 1;
  nb = nb < PATH_SIZE - 1 - na ? nb : PATH_SIZE - 1 - na;
  memmove(out, a, na);
  memmove(out + na, b, nb);
  out[na + nb] = '\0';
}


/* one more zeroed element of *arr (n elements of `elem` bytes, at most max); NULL when full */
static void* growOne(void** arr, int* n, int max, size_t elem) {
  if (*n >= max) {
    return NULL;
  }
  char* grown = realloc(*arr, (size_t)(*n + 1) * elem);
  if (!grown) {
    return NULL;
  }
  *arr = grown;
  char* e = grown + (size_t)(*n)++ * elem;
  memset(e, 0, elem);
  return e;
}


static Node* addNode(Tree* t, const char* path, int kind) {
  void* arr = t->node;
  Node* nd = growOne(&arr, &t->n, MAX_NODES, sizeof *nd);
  t->node = arr;
  if (nd) {
    snprintf(nd->path, sizeof nd->path, "%s", path);
    nd->kind = kind;
  }
  return nd;
}


static Attr* addAttr(Node* nd, const char* name) {
  void* arr = nd->attr;
  Attr* a = growOne(&arr, &nd->nattr, MAX_ATTRS, sizeof *a);
  nd->attr = arr;
  if (a) {
    snprintf(a->name, sizeof a->name, "%s", name);
  }
  return a;
}


static void attrNum(Node* nd, const char* name, double v) {
  Attr* a = addAttr(nd, name);
  if (a) {
    a->type = T_F64;
    a->num[0] = v;
    a->nnum = 1;
  }
}


static void attrStr(Node* nd, const char* name, const char* s) {
  Attr* a = addAttr(nd, name);
  if (a) {
    a->type = T_FSTR;
    a->len = strlen(s) < STR_SIZE - 1 ? strlen(s) : STR_SIZE - 1;
    memcpy(a->str, s, a->len);
  }
}


static size_t shapeElems(int rank, const hsize_t* dims) {
  size_t n = 1;
  for (int i = 0; i < rank; i++) {
    if (dims[i] > MAX_ELEMS || n * dims[i] > MAX_ELEMS) {
      return MAX_ELEMS + 1; /* too large to hold */
    }
    n *= dims[i];
  }
  return n;
}


/* a double dataset of the given shape (data copied, n = the shape's elements) */
static Node* addData(Tree* t, const char* path, int rank, const hsize_t* dims, const double* v) {
  Node* nd = addNode(t, path, K_DATASET);
  if (!nd) {
    return NULL;
  }
  nd->type = T_F64;
  nd->rank = rank;
  memcpy(nd->dims, dims, (size_t)rank * sizeof *dims);
  nd->ndata = shapeElems(rank, dims);
  nd->data = malloc((nd->ndata ? nd->ndata : 1) * sizeof(double));
  if (nd->data) {
    memcpy(nd->data, v, nd->ndata * sizeof(double));
  }
  return nd;
}


static void freeTree(Tree* t) {
  for (int i = 0; i < t->n; i++) {
    free(t->node[i].data);
    free(t->node[i].attr);
  }
  free(t->node);
  memset(t, 0, sizeof *t);
}


static int copyNode(Node* dst, const Node* src) {
  *dst = *src;
  dst->data = NULL;
  dst->attr = NULL;
  if (src->data) {
    dst->data = malloc((src->ndata ? src->ndata : 1) * sizeof(double));
    if (!dst->data) return -1;
    memcpy(dst->data, src->data, src->ndata * sizeof(double));
  }
  if (src->nattr) {
    dst->attr = malloc((size_t)src->nattr * sizeof(Attr));
    if (!dst->attr) return -1;
    memcpy(dst->attr, src->attr, (size_t)src->nattr * sizeof(Attr));
  }
  return 0;
}


static int copyTree(Tree* dst, const Tree* src) {
  memset(dst, 0, sizeof *dst);
  dst->node = calloc((size_t)src->n, sizeof(Node));
  if (!dst->node) return -1;
  dst->libver_latest = src->libver_latest;
  dst->userblock = src->userblock;
  for (int i = 0; i < src->n; i++) {
    dst->n = i + 1;
    if (copyNode(&dst->node[i], &src->node[i]) != 0) return -1;
  }
  return 0;
}


/* ---- templates ---------------------------------------------------------------------------- */

/* a plausible truth for the template's values: chamber j at (±1, ±1)/√2 bends its segment
 * towards the opposite side (Ω1 (+,+), Ω2 (+,-), Ω3 (-,-), Ω4 (-,+): Ω1&Ω2 bend towards -e1),
 * 1.2 rad/MPa and stiffening; stretch, radial growth linear in the pressures */
static const double kChamberDir[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};

static void truth(int seg, const double P[4], double bend[2], double* stretch, double* radial,
                  double* radmax) {
  double sum = 0;
  bend[0] = bend[1] = 0;
  for (int j = 0; j < 4; j++) {
    const double k = 1.2 * (1 + 0.5 * P[j]) * (1 + 0.1 * seg) / sqrt(2.0);
    bend[0] -= k * P[j] * kChamberDir[j][0];
    bend[1] -= k * P[j] * kChamberDir[j][1];
    sum += P[j];
  }
  *stretch = 1 + 0.03 * sum;
  *radial = 0.02 * sum;
  *radmax = 0.05 * sum;
}


typedef struct {
  const char* name;
  const char* kind;
  double ratio[4];
  int probes;
} CaseSpec;

/* the calibration's case list (fem_calibration.c; the gravity case has no chamber pattern) */
static const CaseSpec kCases[] = {
    {"O12", "mode", {1, 1, 0, 0}, 1},      {"O1", "mode", {1, 0, 0, 0}, 0},
    {"O124", "mode", {1, 1, 0, 1}, 0},     {"O1234", "mode", {1, 1, 1, 1}, 1},
    {"O13", "mode", {1, 0, 1, 0}, 0},      {"O12r05", "mode", {1, 0.5, 0, 0}, 0},
    {"O12O34r3", "mode", {1, 1, 1.0 / 3.0, 1.0 / 3.0}, 0},
    {"O1O234r05", "mode", {1, 0.5, 0.5, 0.5}, 0}, {"O1O234r075", "mode", {1, 0.75, 0.75, 0.75}, 0},
    {"O2", "symmetry", {0, 1, 0, 0}, 0},   {"H1", "holdout", {1, 1.0 / 3.0, 0, 0}, 0},
    {"G", "gravity", {0, 0, 0, 0}, 0},
};
#define NCASE ((int)(sizeof kCases / sizeof kCases[0]))
/* the five corner modes (the model needs them all) are the first five */
#define NCORNER 5
/* rows of a template case (MPa between rows) */
#define TPL_ROWS 5
#define TPL_DP 0.1
#define TPL_PROBES 3


static void visitParam(void* user, const char* name, double value) { attrNum(user, name, value); }


static void addCase(Tree* t, const CaseSpec* cs) {
  char g[PATH_SIZE], d[PATH_SIZE];
  snprintf(g, sizeof g, "/cases/%s", cs->name);
  Node* grp = addNode(t, g, K_GROUP);
  if (!grp) return;
  const int gravity = !strcmp(cs->kind, "gravity");
  const int m = gravity ? 2 : TPL_ROWS;
  const double dp = gravity ? 0.025 : TPL_DP;
  attrStr(grp, "kind", cs->kind);
  for (int j = 0; j < 4; j++) {
    char nm[16];
    snprintf(nm, sizeof nm, "ratio%d", j + 1);
    attrNum(grp, nm, cs->ratio[j]);
  }
  attrStr(grp, "status", "complete");
  attrNum(grp, "p_end", (m - 1) * dp);
  attrNum(grp, "p_limit", NAN);
  double p[TPL_ROWS], bend[TPL_ROWS * 6], tw[TPL_ROWS * 3], st[TPL_ROWS * 3], ra[TPL_ROWS * 3],
      rm[TPL_ROWS * 3], tip[TPL_ROWS * 3], tot[TPL_ROWS];
  for (int i = 0; i < m; i++) {
    p[i] = i * dp;
    tot[i] = 0;
    double bx = 0, by = 0, len = 0;
    for (int s = 0; s < 3; s++) {
      double P[4], b[2];
      for (int j = 0; j < 4; j++) P[j] = cs->ratio[j] * p[i];
      truth(s, P, b, &st[3 * i + s], &ra[3 * i + s], &rm[3 * i + s]);
      if (gravity) {
        b[0] = 0.002 * (3 - s) * (i > 0), b[1] = 0; /* the leg's weight bends it a little */
      }
      bend[6 * i + 2 * s] = b[0], bend[6 * i + 2 * s + 1] = b[1];
      tw[3 * i + s] = 1e-4 * p[i];
      tot[i] += hypot(b[0], b[1]) * (180 / 3.14159265358979323846);
      bx += b[0], by += b[1], len += 50 * st[3 * i + s] + (s < 2 ? 8 : 0);
    }
    tip[3 * i] = -25 * bx, tip[3 * i + 1] = -25 * by, tip[3 * i + 2] = len;
  }
  const hsize_t d1[1] = {(hsize_t)m}, d2[2] = {(hsize_t)m, 3}, d3[3] = {(hsize_t)m, 3, 2};
  const struct {
    const char* name;
    int rank;
    const hsize_t* dims;
    const double* v;
  } ds[] = {{"pressure", 1, d1, p},  {"bend", 3, d3, bend},       {"twist", 2, d2, tw},
            {"stretch", 2, d2, st},  {"radial", 2, d2, ra},       {"radial_max", 2, d2, rm},
            {"tip", 2, d2, tip},     {"angle_total_deg", 1, d1, tot}};
  for (size_t q = 0; q < sizeof ds / sizeof ds[0]; q++) {
    joinPath(d, g, "/");
    joinPath(d, d, ds[q].name);
    addData(t, d, ds[q].rank, ds[q].dims, ds[q].v);
  }
  if (!cs->probes) return;
  const int K = TPL_PROBES;
  double pp[TPL_PROBES], ei[TPL_PROBES * 6], ea[TPL_PROBES * 3], pb[TPL_PROBES * 18],
      ps[TPL_PROBES * 9], pt[TPL_PROBES * 9];
  double force[TPL_PROBES * 3];
  const double rbar = 0.25 * (cs->ratio[0] + cs->ratio[1] + cs->ratio[2] + cs->ratio[3]);
  for (int k = 0; k < K; k++) {
    pp[k] = k * TPL_DP;
    force[3 * k] = force[3 * k + 1] = 0.005, force[3 * k + 2] = 0.05;
    for (int s = 0; s < 3; s++) {
      ei[6 * k + 2 * s] = ei[6 * k + 2 * s + 1] = 2800 * (1 + rbar * pp[k]);
      ea[3 * k + s] = 30 * (1 + rbar * pp[k]);
    }
    for (int q = 0; q < 18; q++) pb[18 * k + q] = 1e-3 * (q % 5);
    for (int q = 0; q < 9; q++) ps[9 * k + q] = 1 + 1e-4 * q, pt[9 * k + q] = 0.1 * q;
  }
  const hsize_t k1[1] = {(hsize_t)K}, k2[2] = {(hsize_t)K, 3},
                kk3[3] = {(hsize_t)K, 3, 3}, kk4[4] = {(hsize_t)K, 3, 3, 2},
                kei[3] = {(hsize_t)K, 3, 2};
  const struct {
    const char* name;
    int rank;
    const hsize_t* dims;
    const double* v;
  } pr[] = {{"probe_pressure", 1, k1, pp}, {"probe_force", 2, k2, force},
            {"probe_bend", 4, kk4, pb},    {"probe_stretch", 3, kk3, ps},
            {"probe_tip", 3, kk3, pt},     {"EI", 3, kei, ei},
            {"EA", 2, k2, ea}};
  for (size_t q = 0; q < sizeof pr / sizeof pr[0]; q++) {
    joinPath(d, g, "/");
    joinPath(d, d, pr[q].name);
    addData(t, d, pr[q].rank, pr[q].dims, pr[q].v);
  }
}


static void buildModeTemplate(Tree* t, int ncase) {
  Node* root = addNode(t, "/", K_GROUP);
  attrStr(root, "format", CSR_CAL_FORMAT);
  csr_actuatorVisit(&g_leg, visitParam, root);
  attrNum(root, "fe_mesh_size_mm", 4);
  attrNum(root, "fe_fibre_size_mm", 0);
  attrNum(root, "fe_fibre_split", 1);
  attrNum(root, "fe_p_step_MPa", TPL_DP);
  attrNum(root, "fe_p_cap_MPa", 0);
  attrStr(root, "fe_solver", "mumps-ldlt");
  attrStr(root, "version", "0.1.0");
  addNode(t, "/cases", K_GROUP);
  for (int c = 0; c < ncase; c++) {
    addCase(t, &kCases[c]);
  }
}


/* the `crawlsim bend` layout of the pair mode Ω1&Ω2 (robot_bend_io.h), m rows to 0.3 MPa */
static void buildPairTemplate(Tree* t, int m) {
  Node* root = addNode(t, "/", K_GROUP);
  csr_actuatorVisit(&g_leg, visitParam, root);
  attrStr(root, "model", "fe");
  attrStr(root, "actuator", "leg");
  attrStr(root, "chambers", "1,2");
  attrNum(root, "mesh_size_mm", 4);
  attrStr(root, "units", "length mm, pressure MPa, angle deg, time s");
  attrStr(root, "version", "0.1.0");
  double p[16], ang[16 * 3], tot[16], tip[16 * 3];
  for (int i = 0; i < m; i++) {
    p[i] = 0.3 * i / (m - 1);
    tot[i] = 0;
    for (int s = 0; s < 3; s++) {
      ang[3 * i + s] = 40 * pow(p[i] / 0.3, 1.3) * (1 + 0.05 * s);
      tot[i] += ang[3 * i + s];
    }
    tip[3 * i] = -0.5 * tot[i], tip[3 * i + 1] = 0, tip[3 * i + 2] = 166 - 0.1 * tot[i];
  }
  const hsize_t d1[1] = {(hsize_t)m}, d2[2] = {(hsize_t)m, 3};
  addData(t, "/pressure", 1, d1, p);
  addData(t, "/angle_deg", 2, d2, ang);
  addData(t, "/angle_total_deg", 1, d1, tot);
  addData(t, "/tip_position", 2, d2, tip);
}


/* ---- edits -------------------------------------------------------------------------------- */

static const double kSpecial[] = {0,     -0.0,     1,       -1,        0.5,   1e-300,
                                  5e-324, 1e300,   DBL_MAX, -DBL_MAX,  INFINITY,
                                  -INFINITY, NAN,  1 + 1e-12, 1 - 1e-12, 0.3,
                                  1.0000001, 100001, 2.5,   -1e-9,     0.1,   1e-12,
                                  0.4,   4,       2,       3,         7.5,   0.025};
#define NSPECIAL ((unsigned)(sizeof kSpecial / sizeof kSpecial[0]))

static const char* const kWords[] = {
    CSR_CAL_FORMAT, "crawlsim-fe-calibration 2", "crawlsim-fe-calibration ", "format", "mode",
    "holdout", "symmetry", "gravity", "complete", "ended at 0.25 MPa (limit point)", "ended",
    "1,2", "1,2,3", "2,1", "1,,2", "O12", "O1", "O124", "O1234", "O13", "O12r05", "O12O34r3",
    "O1O234r05", "O1O234r075", "O2", "H1", "H4", "H5", "G", "pressure", "bend", "twist", "stretch", "radial", "radial_max", "tip",
    "angle_total_deg", "probe_pressure", "probe_force", "probe_bend", "probe_stretch",
    "probe_tip", "EI", "EA", "kind", "status", "ratio1", "ratio4", "p_end", "p_limit",
    "chambers", "S1", "C10", "rf", "fe_mesh_size_mm", "fe_solver", "version", "angle_deg",
    "cases", "", " ", "%s%n%x", "\xff\xfe",
    "a-case-name-of-seventy-bytes-to-pass-the-sixty-three-of-the-name-buf"};
#define NWORD ((unsigned)(sizeof kWords / sizeof kWords[0]))


static double pickValue(cszBytes* b, double old) {
  unsigned c = csz_byte(b);
  if (c < NSPECIAL) return kSpecial[c];
  if (c < NSPECIAL + 16) return old * (1 + (c - NSPECIAL - 8) * 1e-10); /* nudge */
  if (c < NSPECIAL + 32) return old * ((int)(c - NSPECIAL - 24)); /* scale, sign */
  if (c < NSPECIAL + 48) return old + (c - NSPECIAL - 40) * 0.05;
  return csz_rawDouble(b);
}


/* text from the input: a dictionary word or up to 99 raw bytes */
static size_t pickText(cszBytes* b, char* out, size_t size) {
  unsigned c = csz_byte(b);
  size_t n;
  if (c < 128) {
    const char* w = kWords[c % NWORD];
    n = strlen(w);
    n = n < size - 1 ? n : size - 1;
    memcpy(out, w, n);
  } else {
    n = csz_byte(b) % 100;
    n = n < size - 1 ? n : size - 1;
    for (size_t i = 0; i < n; i++) out[i] = (char)csz_byte(b);
  }
  out[n] = '\0';
  return n;
}


static Node* pickNode(Tree* t, cszBytes* b, int want_kind) {
  if (t->n == 0) return NULL;
  unsigned k = csz_u16(b) % (unsigned)t->n;
  if (want_kind < 0) return &t->node[k];
  for (int i = 0; i < t->n; i++) {
    Node* nd = &t->node[(k + (unsigned)i) % (unsigned)t->n];
    if (nd->kind == want_kind) return nd;
  }
  return NULL;
}


static int isUnder(const char* path, const char* top) {
  size_t n = strlen(top);
  return !strncmp(path, top, n) && (path[n] == '/' || path[n] == '\0') && strcmp(top, "/");
}


static void removeNodes(Tree* t, const char* top_in) {
  char top[PATH_SIZE];
  snprintf(top, sizeof top, "%s", top_in);
  int w = 0;
  for (int i = 0; i < t->n; i++) {
    if (isUnder(t->node[i].path, top)) {
      free(t->node[i].data);
      free(t->node[i].attr);
    } else {
      t->node[w++] = t->node[i];
    }
  }
  t->n = w;
}


/* new shape: data cycled from the old values, or left unwritten when too large */
static void reshape(Node* nd, int rank, const hsize_t* dims) {
  size_t n = shapeElems(rank, dims);
  double* v = NULL;
  if (n <= MAX_ELEMS) {
    v = malloc((n ? n : 1) * sizeof(double));
    if (!v) return;
    for (size_t i = 0; i < n; i++) {
      v[i] = nd->data && nd->ndata ? nd->data[i % nd->ndata] : (double)i;
    }
  }
  free(nd->data);
  nd->data = v;
  nd->ndata = v ? n : 0;
  nd->rank = rank;
  memcpy(nd->dims, dims, (size_t)rank * sizeof *dims);
  if (!v) nd->layout = L_UNWRITTEN;
  else if (nd->layout == L_UNWRITTEN) nd->layout = L_CHUNKED;
}


static void editShape(Node* nd, cszBytes* b) {
  static const hsize_t kBig[] = {65535, 65537, 100000, 100001, 1u << 20, 1ull << 31,
                                 (1ull << 32) + 1};
  int rank = nd->rank;
  hsize_t dims[MAX_RANK];
  memcpy(dims, nd->dims, sizeof dims);
  unsigned op = csz_byte(b) % 5, c = csz_byte(b);
  int d = rank > 0 ? (int)(c % (unsigned)rank) : 0;
  if (op == 0 && rank > 0) dims[d] = csz_byte(b) % 8;
  if (op == 1 && rank > 0) dims[d] = (c & 0x80) ? dims[d] + 1 : (dims[d] ? dims[d] - 1 : 0);
  if (op == 2 && rank < MAX_RANK) dims[rank++] = csz_byte(b) % 4;
  if (op == 3 && rank > 0) rank--;
  if (op == 4 && rank > 0) dims[d] = kBig[csz_byte(b) % (sizeof kBig / sizeof kBig[0])];
  reshape(nd, rank, dims);
}


static void editAttr(Attr* a, unsigned op, cszBytes* b) {
  switch (op) {
    case 0: a->type = (int)(csz_byte(b) % NTYPE); break;
    case 1: {
      a->rank = (int)(csz_byte(b) % 6) - 1;
      for (int i = 0; i < 4; i++) a->dims[i] = csz_byte(b) % 4;
      break;
    }
    case 2: {
      a->num[0] = pickValue(b, a->num[0]);
      a->nnum = a->nnum > 0 ? a->nnum : 1;
      if (a->type == T_FSTR || a->type == T_VLSTR) a->type = T_F64;
      break;
    }
    default: {
      a->len = pickText(b, a->str, sizeof a->str);
      unsigned pad = csz_byte(b) % 3;
      a->pad = (int)pad;
      a->strsize = pad == 0 ? 0 : pad == 1 ? a->len : a->len + 5;
      if (a->type != T_FSTR && a->type != T_VLSTR) a->type = T_FSTR;
      break;
    }
  }
}


static void setLast(char* path, const char* name) {
  char* slash = strrchr(path, '/');
  size_t keep = slash ? (size_t)(slash - path) + 1 : 0;
  snprintf(path + keep, PATH_SIZE - keep, "%s", name);
}


/* a node other than the root (old, its path) and a new last name for it (now): 0, or -1 when
 * the root was picked */
static int pickRename(Tree* t, cszBytes* b, char* old, char* now) {
  Node* nd = pickNode(t, b, -1);
  if (!nd || !strcmp(nd->path, "/")) {
    return -1;
  }
  char name[NAME_SIZE];
  joinPath(old, nd->path, "");
  pickText(b, name, sizeof name);
  joinPath(now, old, "");
  setLast(now, name);
  return 0;
}


static void editOne(Tree* t, cszBytes* b) {
  unsigned op = csz_byte(b) % 16;
  Node* nd;
  switch (op) {
    case 0: /* delete a node and what is under it */
      if ((nd = pickNode(t, b, -1)) && strcmp(nd->path, "/")) removeNodes(t, nd->path);
      break;
    case 1: /* delete an attribute */
      if ((nd = pickNode(t, b, -1)) && nd->nattr) {
        unsigned j = csz_byte(b) % (unsigned)nd->nattr;
        memmove(&nd->attr[j], &nd->attr[j + 1], (size_t)(nd->nattr - 1 - (int)j) * sizeof(Attr));
        nd->nattr--;
      }
      break;
    case 2: case 3: case 4: case 5: /* an attribute's type, dataspace, number, text */
      if ((nd = pickNode(t, b, -1)) && nd->nattr) {
        editAttr(&nd->attr[csz_byte(b) % (unsigned)nd->nattr], op - 2, b);
      }
      break;
    case 6: /* one value of a dataset */
      if ((nd = pickNode(t, b, K_DATASET)) && nd->data && nd->ndata) {
        size_t i = csz_u16(b) % nd->ndata;
        nd->data[i] = pickValue(b, nd->data[i]);
      }
      break;
    case 7:
      if ((nd = pickNode(t, b, K_DATASET))) editShape(nd, b);
      break;
    case 8:
      if ((nd = pickNode(t, b, K_DATASET))) nd->type = (int)(csz_byte(b) % NTYPE);
      break;
    case 9:
      if ((nd = pickNode(t, b, K_DATASET)) && nd->layout != L_UNWRITTEN) {
        nd->layout = (int)(csz_byte(b) % (NLAYOUT - 1));
      }
      break;
    case 10: { /* rename (what is under it moves along) */
      char old[PATH_SIZE], now[PATH_SIZE];
      if (pickRename(t, b, old, now) != 0) break;
      size_t n = strlen(old);
      for (int i = 0; i < t->n; i++) {
        if (isUnder(t->node[i].path, old)) {
          char rest[PATH_SIZE];
          joinPath(rest, t->node[i].path + n, "");
          joinPath(t->node[i].path, now, rest);
        }
      }
      break;
    }
    case 11: { /* duplicate a node and what is under it, under a new last name */
      char old[PATH_SIZE], now[PATH_SIZE];
      if (pickRename(t, b, old, now) != 0) break;
      size_t n = strlen(old);
      int count = t->n;
      for (int i = 0; i < count && t->n < MAX_NODES; i++) {
        if (!isUnder(t->node[i].path, old)) continue;
        Node copy;
        if (copyNode(&copy, &t->node[i]) != 0) {
          free(copy.data);
          free(copy.attr);
          break;
        }
        joinPath(copy.path, now, t->node[i].path + n);
        Node* slot = addNode(t, "", K_GROUP);
        if (!slot) {
          free(copy.data);
          free(copy.attr);
          break;
        }
        *slot = copy;
      }
      break;
    }
    case 12: { /* a stray object */
      unsigned kind = csz_byte(b) % 5;
      char name[NAME_SIZE], path[PATH_SIZE];
      pickText(b, name, sizeof name);
      joinPath(path, (kind & 1) ? "/" : "/cases/", name);
      Node* other = pickNode(t, b, -1);
      char target[PATH_SIZE];
      snprintf(target, sizeof target, "%s", other ? other->path : "/nowhere");
      if (kind == 0) {
        const hsize_t d3[1] = {3};
        const double v[3] = {0, 0.1, 0.2};
        addData(t, path, 1, d3, v);
      } else if (kind == 1) {
        addNode(t, path, K_GROUP);
      } else if ((nd = addNode(t, path, kind == 2 ? K_SOFT : kind == 3 ? K_HARD : K_EXTERNAL))) {
        snprintf(nd->target, sizeof nd->target, "%s", kind == 4 ? "/x" : target);
        if ((csz_byte(b) & 1) && kind == 2) snprintf(nd->target, sizeof nd->target, "/nowhere");
      }
      break;
    }
    case 13: { /* the file as a whole */
      unsigned c = csz_byte(b) % 3;
      if (c == 0) t->libver_latest ^= 1;
      if (c == 1) t->userblock ^= 1;
      if (c == 2 && (nd = pickNode(t, b, -1))) { /* dense attribute storage */
        for (int i = 0; i < 12; i++) {
          char nm[32];
          snprintf(nm, sizeof nm, "extra_%d_%d", nd->nattr, i);
          attrNum(nd, nm, i);
        }
      }
      break;
    }
    case 14: /* a dataset's values all at once */
      if ((nd = pickNode(t, b, K_DATASET)) && nd->data) {
        unsigned c = csz_byte(b) % 4;
        double v = pickValue(b, 1.0);
        for (size_t i = 0; i < nd->ndata; i++) {
          double* x = &nd->data[i];
          *x = c == 0 ? *x * v : c == 1 ? *x + v : c == 2 ? v : nd->data[nd->ndata - 1 - i];
        }
      }
      break;
    default: /* a group becomes a dataset or the other way round */
      if ((nd = pickNode(t, b, -1)) && strcmp(nd->path, "/")) {
        char p[PATH_SIZE];
        snprintf(p, sizeof p, "%s", nd->path);
        int was_group = nd->kind == K_GROUP;
        Attr* attr = nd->attr;
        int nattr = nd->nattr;
        nd->attr = NULL;
        nd->nattr = 0;
        removeNodes(t, p); /* nd is gone */
        const hsize_t d1[1] = {2};
        const double v[2] = {0, 0.1};
        Node* nn = was_group ? addData(t, p, 1, d1, v) : addNode(t, p, K_GROUP);
        if (nn) {
          nn->attr = attr;
          nn->nattr = nattr;
        } else {
          free(attr);
        }
      }
      break;
  }
}


/* ---- writing a tree ----------------------------------------------------------------------- */

static hid_t fileType(int type, size_t strsize, int pad) {
  switch (type) {
    case T_F64: return H5Tcopy(H5T_IEEE_F64LE);
    case T_F32: return H5Tcopy(H5T_IEEE_F32LE);
    case T_I32: return H5Tcopy(H5T_STD_I32LE);
    case T_U8: return H5Tcopy(H5T_STD_U8LE);
    case T_LDBL: return H5Tcopy(H5T_NATIVE_LDOUBLE);
    default: {
      hid_t s = H5Tcopy(H5T_C_S1);
      if (type == T_VLSTR) {
        H5Tset_size(s, H5T_VARIABLE);
      } else {
        H5Tset_size(s, strsize ? strsize : 1);
        H5Tset_strpad(s, pad == 0 ? H5T_STR_NULLTERM : pad == 1 ? H5T_STR_NULLPAD
                                                                 : H5T_STR_SPACEPAD);
      }
      return s;
    }
  }
}


/* write n values (cycled from v[nv]) or strings into an attribute or dataset `obj` */
static void writeValues(hid_t obj, int is_attr, int type, size_t n, const double* v, size_t nv,
                        const char* str, size_t len, size_t strsize, hid_t ftype) {
  if (n == 0) return;
  if (type == T_FSTR || type == T_VLSTR) {
    char numtext[32];
    if (!str) { /* a numeric dataset turned into strings: its first value as text */
      snprintf(numtext, sizeof numtext, "%.6g", nv ? v[0] : 0.0);
      str = numtext;
      len = strlen(numtext);
    }
    if (type == T_VLSTR) {
      char* one = malloc(len + 1);
      char** ptrs = malloc(n * sizeof *ptrs);
      if (one && ptrs) {
        memcpy(one, str, len);
        one[len] = '\0';
        for (size_t i = 0; i < n; i++) ptrs[i] = one;
        if (is_attr) H5Awrite(obj, ftype, ptrs);
        else H5Dwrite(obj, ftype, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs);
      }
      free(one);
      free(ptrs);
      return;
    }
    size_t sz = H5Tget_size(ftype);
    char* buf = calloc(n, sz ? sz : 1);
    if (!buf) return;
    for (size_t i = 0; i < n; i++) memcpy(buf + i * sz, str, len < sz ? len : sz);
    (void)strsize;
    if (is_attr) H5Awrite(obj, ftype, buf);
    else H5Dwrite(obj, ftype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
    free(buf);
    return;
  }
  double* buf = malloc(n * sizeof *buf);
  if (!buf) return;
  for (size_t i = 0; i < n; i++) buf[i] = nv ? v[i % nv] : 0;
  if (is_attr) H5Awrite(obj, H5T_NATIVE_DOUBLE, buf);
  else H5Dwrite(obj, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  free(buf);
}


static void writeAttr(hid_t obj, const Attr* a) {
  size_t n = 0;
  hid_t space;
  if (a->rank < 0) {
    space = H5Screate(H5S_NULL);
  } else if (a->rank == 0) {
    space = H5Screate(H5S_SCALAR);
    n = 1;
  } else {
    space = H5Screate_simple(a->rank, a->dims, NULL);
    n = shapeElems(a->rank, a->dims);
  }
  size_t strsize = a->strsize ? a->strsize : a->len + 1;
  hid_t ft = fileType(a->type, strsize, a->pad);
  hid_t at = H5Acreate2(obj, a->name, ft, space, H5P_DEFAULT, H5P_DEFAULT);
  if (at >= 0) {
    int is_str = a->type == T_FSTR || a->type == T_VLSTR;
    writeValues(at, 1, a->type, n, a->num, (size_t)a->nnum, is_str ? a->str : NULL, a->len,
                strsize, ft);
    H5Aclose(at);
  }
  H5Tclose(ft);
  H5Sclose(space);
}


static void writeDataset(hid_t f, hid_t lcpl, const Node* nd) {
  hid_t space = nd->rank == 0 ? H5Screate(H5S_SCALAR)
                              : H5Screate_simple(nd->rank, nd->dims, NULL);
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  int chunked = nd->layout >= L_CHUNKED && nd->rank > 0;
  if (nd->layout == L_COMPACT) {
    H5Pset_layout(dcpl, H5D_COMPACT);
  } else if (chunked) {
    hsize_t chunk[MAX_RANK];
    for (int i = 0; i < nd->rank; i++) {
      chunk[i] = nd->dims[i] == 0 ? 1 : nd->dims[i] < 64 ? nd->dims[i] : 64;
    }
    H5Pset_chunk(dcpl, nd->rank, chunk);
    if (nd->layout == L_SHUFFLE_DEFLATE) H5Pset_shuffle(dcpl);
    if (nd->layout == L_DEFLATE || nd->layout == L_SHUFFLE_DEFLATE) H5Pset_deflate(dcpl, 1);
  }
  hid_t ft = fileType(nd->type, 16, 0);
  hid_t d = H5Dcreate2(f, nd->path, ft, space, lcpl, dcpl, H5P_DEFAULT);
  if (d < 0) {
    /* too large for a compact dataset, or a shape chunks refuse: plain storage */
    H5Pclose(dcpl);
    dcpl = H5Pcreate(H5P_DATASET_CREATE);
    d = H5Dcreate2(f, nd->path, ft, space, lcpl, dcpl, H5P_DEFAULT);
  }
  if (d >= 0) {
    if (nd->data && nd->layout != L_UNWRITTEN) {
      writeValues(d, 0, nd->type, nd->ndata, nd->data, nd->ndata, NULL, 0, 16, ft);
    }
    for (int i = 0; i < nd->nattr; i++) writeAttr(d, &nd->attr[i]);
    H5Dclose(d);
  }
  H5Tclose(ft);
  H5Pclose(dcpl);
  H5Sclose(space);
}


static int writeTree(const Tree* t, const char* path) {
  hid_t fcpl = H5Pcreate(H5P_FILE_CREATE), fapl = H5Pcreate(H5P_FILE_ACCESS);
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  if (t->userblock) H5Pset_userblock(fcpl, 512);
  if (t->libver_latest) H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
  hid_t f = H5Fcreate(path, H5F_ACC_TRUNC, fcpl, fapl);
  if (f >= 0) {
    for (int i = 0; i < t->n; i++) {
      const Node* nd = &t->node[i];
      if (nd->kind == K_DATASET) {
        writeDataset(f, lcpl, nd);
        continue;
      }
      if (nd->kind == K_SOFT) {
        H5Lcreate_soft(nd->target, f, nd->path, lcpl, H5P_DEFAULT);
        continue;
      }
      if (nd->kind == K_HARD) {
        H5Lcreate_hard(f, nd->target, f, nd->path, lcpl, H5P_DEFAULT);
        continue;
      }
      if (nd->kind == K_EXTERNAL) {
        H5Lcreate_external("crawlsim-fuzz-no-such-file.h5", nd->target, f, nd->path, lcpl,
                           H5P_DEFAULT);
        continue;
      }
      hid_t g = !strcmp(nd->path, "/") ? H5Gopen2(f, "/", H5P_DEFAULT)
                                       : H5Gcreate2(f, nd->path, lcpl, H5P_DEFAULT, H5P_DEFAULT);
      if (g >= 0) {
        for (int j = 0; j < nd->nattr; j++) writeAttr(g, &nd->attr[j]);
        H5Gclose(g);
      }
    }
    H5Fclose(f);
  }
  H5Pclose(lcpl);
  H5Pclose(fapl);
  H5Pclose(fcpl);
  return f >= 0 ? 0 : -1;
}


/* ---- the harness -------------------------------------------------------------------------- */

int csz_harnessInit(void) {
  csError err;
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  if (csr_actuatorPreset(&g_leg, "leg", &err) != CS_OK || !csz_tempPath(0, ".h5")) {
    return 1;
  }
  buildModeTemplate(&g_tpl[TPL_MODE_FULL], NCASE);
  buildModeTemplate(&g_tpl[TPL_MODE_CORNERS], NCORNER);
  buildPairTemplate(&g_tpl[TPL_PAIR], 13);
  buildPairTemplate(&g_tpl[TPL_PAIR_SHORT], 2);
  return 0;
}


static long openObjects(void) { return (long)H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL); }


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  cszBytes b = {data, size, 0};
  const char* path = csz_tempPath(0, ".h5");
  Tree t;
  if (copyTree(&t, &g_tpl[csz_byte(&b) % NTPL]) != 0) {
    csz_fail("out of memory copying a template");
  }
  while (csz_more(&b)) {
    editOne(&t, &b);
  }
  int wrote = writeTree(&t, path);
  freeTree(&t);
  if (wrote != 0) {
    csz_fail("cannot create %s", path);
  }
  long before = openObjects();
  if (before != 0) {
    csz_fail("the harness left %ld HDF5 objects open", before);
  }
  csrCalibration* c = csr_calibrationOpen(path, &g_leg, err);
  csStatus st = c ? CS_OK : err->status;
  csz_checkError(st, c != NULL, err, path, data, size, CSZ_FILE);
  if (openObjects() != 0) {
    csz_fail("the reader left %ld HDF5 objects open (%s)", openObjects(),
             c ? "accepted" : err->msg);
  }
  if (c) {
    csrBendMap map = csr_calibrationMap(c);
    csz_checkBendMap(&map, 5);
    csrRodCalibration rod;
    if (csr_calibrationRod(c, &rod)) {
      csz_checkRodCalibration(&rod, map.p_max,
                              csr_calModelStiffnessPMax(csr_calibrationModel(c)), 5);
    }
    csr_calibrationClose(c);
  }
  return st;
}
