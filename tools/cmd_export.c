/* cmd_export.c: `crawlsim export FILE.h5 --csv [--out DIR]`: a run file's tracks as CSV for
 * spreadsheet users (issue 36).
 *
 * Writes, for the run file RUN.h5 (core/sim_run.c's layout, docs/reference/output.md):
 *   DIR/RUN_tracks.csv: one row per output sample: time_s, the support's displacement from its
 *     start x_mm, y_mm, z_mm (world frame: x forward, y up, z to the robot's right), its
 *     orientation quaternion qw, qx, qy, qz (body to world), the terrain's total force on the
 *     robot Fx_N, Fy_N, Fz_N (world), and when the file has them the per-foot force
 *     <leg>_F{x,y,z}_N and stance state <leg>_stance (1 stance, 0 swing) of legs A..H;
 *   DIR/RUN_pressure.csv: time_s and the 96 chamber pressures in MPa, columns named as in a
 *     gait table (A_II1_O1 ...; docs/reference/formats.md).
 * Numbers are written with 9 significant digits (%.9g), a comma between fields, a header line
 * with units in the names. Bad input (no such file, not a run file, a missing or misshapen
 * dataset, an unwritable DIR) is one line "crawlsim export: <file>: <cause>" and exit 1. */
#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_commands.h"
#include "cs_opts.h"
#include "gaits_labels.h"

enum { NLEG = 8, NCHAMBER = 96 };

static const csxOpt kExportOpts[] = {
    {"--csv", NULL, "on (the only format today)", "write the tracks as CSV"},
    {"--out", "DIR", "the directory of FILE.h5",
     "where RUN_tracks.csv and RUN_pressure.csv are written (must exist)"},
};

static const csxOptTable kExportTable = {
    "export", "FILE.h5",
    "Write a run file's tracks as CSV for spreadsheets: RUN_tracks.csv (time, the support's "
    "displacement and orientation, the terrain's force on the robot, and per foot its force and "
    "stance state when the run recorded them) and RUN_pressure.csv (the 96 chamber pressures). "
    "Frames and units: docs/reference/output.md.",
    kExportOpts, CSX_NOPT(kExportOpts), NULL};

/* one dataset read whole as doubles */
typedef struct {
  double* v;
  hsize_t dims[3];
  int rank;
} Array;


/* read `path` of file f into a (allocated); `need` 1: absent is an error; returns 0 ok, 1 absent
 * (need 0), -1 error with msg filled */
static int readArray(hid_t f, const char* path, int need, Array* a, char* msg, size_t n) {
  memset(a, 0, sizeof *a);
  if (H5Lexists(f, path, H5P_DEFAULT) <= 0) {
    if (need) snprintf(msg, n, "no dataset %s (not a crawlsim run file?)", path);
    return need ? -1 : 1;
  }
  hid_t ds = H5Dopen2(f, path, H5P_DEFAULT);
  hid_t sp = ds >= 0 ? H5Dget_space(ds) : -1;
  a->rank = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
  int ok = a->rank >= 1 && a->rank <= 3 && H5Sget_simple_extent_dims(sp, a->dims, NULL) >= 0;
  size_t count = 1;
  for (int k = 0; ok && k < a->rank; k++) count *= (size_t)a->dims[k];
  if (ok) {
    a->v = malloc((count ? count : 1) * sizeof *a->v);
    ok = a->v && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a->v) >= 0;
  }
  if (sp >= 0) H5Sclose(sp);
  if (ds >= 0) H5Dclose(ds);
  if (!ok) {
    free(a->v);
    a->v = NULL;
    snprintf(msg, n, "cannot read dataset %s", path);
    return -1;
  }
  return 0;
}


/* a is [N, cols] (cols 0: [N]) */
static int shapeIs(const Array* a, hsize_t N, int rank, hsize_t d1, hsize_t d2) {
  return a->rank == rank && a->dims[0] == N && (rank < 2 || a->dims[1] == d1) &&
         (rank < 3 || a->dims[2] == d2);
}


/* DIR/<stem of h5><suffix> */
static void outPath(const char* dir, const char* h5, const char* suffix, char* buf, size_t n) {
  const char* base = strrchr(h5, '/');
  base = base ? base + 1 : h5;
  size_t len = strlen(base);
  if (len > 3 && !strcmp(base + len - 3, ".h5")) len -= 3;
  if (dir) {
    snprintf(buf, n, "%s/%.*s%s", dir, (int)len, base, suffix);
  } else {
    snprintf(buf, n, "%.*s%.*s%s", (int)(base - h5), h5, (int)len, base, suffix);
  }
}


static int writeTracks(const char* path, hsize_t N, const Array* t, const Array* x,
                       const Array* q, const Array* F, const Array* ff, const Array* st,
                       char* msg, size_t n) {
  errno = 0;
  FILE* o = fopen(path, "w");
  if (!o) {
    snprintf(msg, n, "%s: cannot write: %s", path, strerror(errno));
    return -1;
  }
  fputs("time_s,x_mm,y_mm,z_mm,qw,qx,qy,qz,Fx_N,Fy_N,Fz_N", o);
  for (int k = 0; ff->v && k < NLEG; k++) {
    fprintf(o, ",%c_Fx_N,%c_Fy_N,%c_Fz_N", 'A' + k, 'A' + k, 'A' + k);
  }
  for (int k = 0; st->v && k < NLEG; k++) {
    fprintf(o, ",%c_stance", 'A' + k);
  }
  fputc('\n', o);
  for (hsize_t i = 0; i < N; i++) {
    fprintf(o, "%.9g", t->v[i]);
    for (int c = 0; c < 3; c++) fprintf(o, ",%.9g", x->v[3 * i + c]);
    for (int c = 0; c < 4; c++) fprintf(o, ",%.9g", q->v[4 * i + c]);
    for (int c = 0; c < 3; c++) fprintf(o, ",%.9g", F->v[3 * i + c]);
    for (int c = 0; ff->v && c < 3 * NLEG; c++) fprintf(o, ",%.9g", ff->v[3 * NLEG * i + c]);
    for (int k = 0; st->v && k < NLEG; k++) fprintf(o, ",%.0f", st->v[NLEG * i + k]);
    fputc('\n', o);
  }
  if (fclose(o) != 0) {
    snprintf(msg, n, "%s: write failed", path);
    return -1;
  }
  return 0;
}


static int writePressure(const char* path, hsize_t N, const Array* t, const Array* p, char* msg,
                         size_t n) {
  errno = 0;
  FILE* o = fopen(path, "w");
  if (!o) {
    snprintf(msg, n, "%s: cannot write: %s", path, strerror(errno));
    return -1;
  }
  fputs("time_s", o);
  for (int l = 1; l <= NCHAMBER; l++) {
    char name[CSG_LABEL_NAME_SIZE];
    csg_labelName(l, name, sizeof name);
    fprintf(o, ",%s_MPa", name);
  }
  fputc('\n', o);
  for (hsize_t i = 0; i < N; i++) {
    fprintf(o, "%.9g", t->v[i]);
    for (int l = 0; l < NCHAMBER; l++) fprintf(o, ",%.9g", p->v[NCHAMBER * i + l]);
    fputc('\n', o);
  }
  if (fclose(o) != 0) {
    snprintf(msg, n, "%s: write failed", path);
    return -1;
  }
  return 0;
}


int csx_cmdExport(int argc, char** argv) {
  const char* in = NULL;
  const char* dir = NULL;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kExportTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kExportTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      if (in) {
        fprintf(stderr, "crawlsim export: unexpected argument '%.200s' (one FILE.h5)\n", it.value);
        return 1;
      }
      in = it.value;
    } else if (csx_optIs(it.opt, "--out")) {
      dir = it.value;
    } /* --csv: the one format */
  }
  if (!in) {
    fprintf(stderr, "crawlsim export: missing FILE.h5 (see crawlsim export --help)\n");
    return 1;
  }
  char msg[1200] = "";
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* our one line instead of HDF5's error stack */
  FILE* probe = fopen(in, "rb");
  if (!probe) {
    fprintf(stderr, "crawlsim export: %s: %s\n", in, strerror(errno));
    return 1;
  }
  fclose(probe);
  if (H5Fis_hdf5(in) <= 0) {
    fprintf(stderr, "crawlsim export: %s: not an HDF5 file\n", in);
    return 1;
  }
  hid_t f = H5Fopen(in, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    fprintf(stderr, "crawlsim export: %s: cannot open\n", in);
    return 1;
  }
  Array t = {0}, x = {0}, q = {0}, F = {0}, p = {0}, ff = {0}, st = {0};
  int rc = 1;
  hsize_t N = 0;
  if (readArray(f, "/time", 1, &t, msg, sizeof msg) || readArray(f, "/support/position", 1, &x,
      msg, sizeof msg) || readArray(f, "/support/orientation", 1, &q, msg, sizeof msg) ||
      readArray(f, "/contact/force", 1, &F, msg, sizeof msg) ||
      readArray(f, "/pressure", 1, &p, msg, sizeof msg) ||
      readArray(f, "/contact/foot_force", 0, &ff, msg, sizeof msg) < 0 ||
      readArray(f, "/contact/stance", 0, &st, msg, sizeof msg) < 0) {
    goto done;
  }
  N = t.rank == 1 ? t.dims[0] : 0;
  if (t.rank != 1 || !shapeIs(&x, N, 2, 3, 0) || !shapeIs(&q, N, 2, 4, 0) ||
      !shapeIs(&F, N, 2, 3, 0) || !shapeIs(&p, N, 2, NCHAMBER, 0) ||
      (ff.v && !shapeIs(&ff, N, 3, NLEG, 3)) || (st.v && !shapeIs(&st, N, 2, NLEG, 0))) {
    snprintf(msg, sizeof msg, "the series' shapes do not match /time's %llu samples (not a "
             "crawlsim run file?)", (unsigned long long)N);
    goto done;
  }
  char tracks[1024], pres[1024];
  outPath(dir, in, "_tracks.csv", tracks, sizeof tracks);
  outPath(dir, in, "_pressure.csv", pres, sizeof pres);
  if (writeTracks(tracks, N, &t, &x, &q, &F, &ff, &st, msg, sizeof msg) ||
      writePressure(pres, N, &t, &p, msg, sizeof msg)) {
    fprintf(stderr, "crawlsim export: %s\n", msg);
    msg[0] = '\0';
    goto done;
  }
  printf("%s: %llu samples -> %s, %s\n", in, (unsigned long long)N, tracks, pres);
  rc = 0;
done:
  if (rc && msg[0]) fprintf(stderr, "crawlsim export: %s: %s\n", in, msg);
  free(t.v);
  free(x.v);
  free(q.v);
  free(F.v);
  free(p.v);
  free(ff.v);
  free(st.v);
  H5Fclose(f);
  return rc;
}
