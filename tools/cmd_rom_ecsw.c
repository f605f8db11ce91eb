/* cmd_rom_ecsw.c: `crawlsim rom ecsw-matrix` (cmd_rom.c holds the subcommand table): every
 * element's reduced force at the basis' training snapshots, the matrices of tools/rom_ecsw.py's
 * NNLS. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include "cmd_fe_threads.h"
#include "core_math.h"
#include "core_clock.h"
#include "cs_commands.h"
#include "cs_opts.h"
#include "cmd_rom_common.h"
#include "cs_signal.h"
#include "fem_measure.h"
#include "fem_rom_act.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

static const csxOpt kEcswOpts[] = {
    {"--basis", "BASIS.h5", NULL,
     "the reduced basis of tools/rom_basis.py, with its training snapshots (required)"},
    {"--leg-file", "LEG.h5", "none: the model built from --basis (gmsh, the chamber forms)",
     "the model from this every-element leg file of the same basis (crawlsim rom leg-file "
     "--basis BASIS.h5): no gmsh, no chamber forms; the training snapshots still from --basis"},
    {"--out", "A.h5", NULL, "the matrices' file (required)"},
    {"--work", "DIR", ".", "where gmsh's files of the basis' mesh are written"},
    {"--stride", "K", "1",
     "every K-th training snapshot only (1 .. 64): the rows grow with the snapshots times the "
     "basis size, the matrices with the elements besides"},
    {"--only", "SET", "both: tet and fibre",
     "write this element set's matrices only (tet or fibre): a set's fit does not need the "
     "other's"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kEcswTable = {
    "rom ecsw-matrix", "",
    "Every element's reduced force at each training snapshot of the basis file (rows snapshot x "
    "coordinate, a column per element; one matrix for the Tet10s, /A_tet, one for the fibres, "
    "/A_fibre; the chambers' pressure loads are exact and not fitted), for tools/rom_ecsw.py's "
    "NNLS. A mixed basis (pressure modes P, m of them) adds to each snapshot's Tet10 rows the "
    "element's constraint share P_e (v_e - V_e), and /A_tet_pressure holds each Tet10's share of "
    "the pressure matrix, so that the weights keep the reduced pressures. A fibre strain basis "
    "(Qf, mf modes) adds to each snapshot's fibre rows the fibre's shares W_f Q_f E_f and W_f "
    "Q_f S(Ebar_f), and /A_fibre_projection holds each fibre's share of the projection matrix "
    "G = sum W_f Q_f Q_f^T (fem/fem_rom_fibre.h).",
    kEcswOpts, CSX_NOPT(kEcswOpts), NULL};

/* a constant matrix's element shares, e.g. the pressure matrix sum_e (V_e / kappa) P_e P_e^T:
 * column e (of cols) holds the lower triangle of c_e B_e B_e^T, B_e row e of B (cols x m),
 * c_e = scale x[e] (y ? y[e] : 1), into dataset `name`; 0, or 1 after one error line */
static int writeOuterRows(csH5File* f, const char* name, int cols_i, int m, const double* B,
                          const double* x, const double* y, double scale) {
  const size_t rows = (size_t)m * (size_t)(m + 1) / 2, cols = (size_t)cols_i;
  double* A = malloc(rows * cols * sizeof(double) + 1);
  if (!A) {
    fprintf(stderr, "crawlsim rom: out of memory (%zu x %zu)\n", rows, cols);
    return 1;
  }
  for (size_t e = 0; e < cols; e++) {
    const double* Be = B + e * (size_t)m;
    const double c = scale * x[e] * (y ? y[e] : 1.0);
    size_t row = 0;
    for (int i = 0; i < m; i++) {
      for (int j = 0; j <= i; j++) {
        A[row++ * cols + e] = c * Be[i] * Be[j];
      }
    }
  }
  const size_t dims[2] = {rows, cols};
  csError err;
  cs_errorClear(&err);
  const int rc = cs_h5WriteDoubles(f, name, 2, dims, A, &err) != CS_OK;
  if (rc) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
  }
  free(A);
  return rc;
}

/* a leg file stands in for --basis's model only when it is that basis' model with every
 * element at weight 1 (each column is one element's force at the unreduced state): the sizes
 * and the bases V, P, Qf bit for bit, every Tet10 and fibre kept; 1 after one error line */
static int ecswLegFileMatches(const char* legf, const char* basis, const csfRomActuator* ra) {
  const csfRom* r = ra->rom;
  const int nt = ra->fe.mesh->ntet, nf = ra->fe.model->nfib;
  if (r->nel[CSF_ROM_SET_TET] != nt || r->nel[CSF_ROM_SET_FIBRE] != nf) {
    fprintf(stderr, "crawlsim rom: ecsw-matrix: %s keeps %d of %d Tet10 and %d of %d fibre "
            "elements: the matrices need its every-element model (rom leg-file without "
            "--weights)\n", legf, r->nel[CSF_ROM_SET_TET], nt, r->nel[CSF_ROM_SET_FIBRE], nf);
    return 1;
  }
  for (int e = 0; e < nt; e++) {
    if (r->w[CSF_ROM_SET_TET][e] != 1.0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: Tet10 %d has weight %.17g, not 1\n", legf,
              e, r->w[CSF_ROM_SET_TET][e]);
      return 1;
    }
  }
  for (int e = 0; e < nf; e++) {
    if (r->w[CSF_ROM_SET_FIBRE][e] != 1.0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: fibre element %d has weight %.17g, not 1\n",
              legf, e, r->w[CSF_ROM_SET_FIBRE][e]);
      return 1;
    }
  }
  const size_t nd = (size_t)ra->fe.model->ndof;
  const struct {
    const char* name;
    const double* x;
    size_t cnt;
  } mat[3] = {{"V", r->V, nd * (size_t)r->n},
              {"P", r->P, (size_t)nt * (size_t)r->m},
              {"Qf", r->Qf, (size_t)nf * (size_t)r->mf}};
  int rc = 0;
  H5E_BEGIN_TRY {
    const hid_t f = H5Fopen(basis, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) {
      fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: cannot open the basis file\n", basis);
      rc = 1;
    }
    for (int k = 0; k < 3 && rc == 0; k++) {
      if (mat[k].cnt == 0) {
        continue;
      }
      hsize_t dims[2] = {0, 0};
      H5T_class_t cls;
      size_t sz;
      double* x = NULL;
      if (H5LTfind_dataset(f, mat[k].name) <= 0 ||
          H5LTget_dataset_info(f, mat[k].name, dims, &cls, &sz) < 0 ||
          (size_t)dims[0] * (size_t)dims[1] != mat[k].cnt) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s is not the model of %s: no /%s of its "
                "size there\n", legf, basis, mat[k].name);
        rc = 1;
      } else if (!(x = malloc(mat[k].cnt * sizeof(double)))) {
        fprintf(stderr, "crawlsim rom: out of memory (/%s of %s)\n", mat[k].name, basis);
        rc = 1;
      } else if (H5LTread_dataset_double(f, mat[k].name, x) < 0) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s: /%s unreadable\n", basis, mat[k].name);
        rc = 1;
      } else if (memcmp(x, mat[k].x, mat[k].cnt * sizeof(double)) != 0) {
        fprintf(stderr, "crawlsim rom: ecsw-matrix: %s is not the model of %s: its /%s differs\n",
                legf, basis, mat[k].name);
        rc = 1;
      }
      free(x);
    }
    if (f >= 0) {
      H5Fclose(f);
    }
  }
  H5E_END_TRY;
  return rc;
}

/* the element force matrices of the ECSW fit (tools/rom_ecsw.py) */
int csx_cmdRomEcswMatrix(int argc, char** argv) {
  const char* basis = NULL, *out = NULL, *work = ".", *actname = "leg", *legf = NULL;
  const char* sets[CSX_ROM_MAX_SETS];
  int nset = 0, stride = 1, only = -1;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kEcswTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kEcswTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kEcswTable, it.value);
    }
    const char* v = it.value;
    if (csx_optIs(it.opt, "--basis")) {
      basis = v;
    } else if (csx_optIs(it.opt, "--leg-file")) {
      legf = v;
    } else if (csx_optIs(it.opt, "--out")) {
      out = v;
    } else if (csx_optIs(it.opt, "--work")) {
      work = v;
    } else if (csx_optIs(it.opt, "--stride")) {
      double d;
      if (csx_romParseNumber("--stride", v, 1, 64, &d)) {
        return 1;
      }
      if (d != floor(d)) {
        fprintf(stderr, "crawlsim rom: --stride %s: not a whole number\n", v);
        return 1;
      }
      stride = (int)d;
    } else if (csx_optIs(it.opt, "--only")) {
      only = !strcmp(v, "tet") ? CSF_ROM_SET_TET : !strcmp(v, "fibre") ? CSF_ROM_SET_FIBRE : -2;
      if (only == -2) {
        fprintf(stderr, "crawlsim rom: --only '%s': expected tet or fibre\n", v);
        return 1;
      }
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--set") &&
               csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS)) {
      return 1;
    }
  }
  if (!basis || !out) {
    fprintf(stderr, "crawlsim rom: ecsw-matrix needs --basis FILE and --out FILE\n");
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  csfRomActuator ra;
  if (legf ? csx_romOpenLegFile(actname, sets, nset, legf, NULL, &act, &ra, NULL)
           : csx_romOpen(actname, sets, nset, basis, NULL, work, "ecsw_mesh", &act, &ra)) {
    return 1;
  }
  if (legf && ecswLegFileMatches(legf, basis, &ra)) {
    csf_romActuatorDestroy(&ra);
    return 1;
  }
  const int n = ra.rom->n;
  int ns = 0;
  double *q, *p, *g, *F;
  if (csf_romBasisReadTraining(basis, n, &ns, &q, &p, &g, &F, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    csf_romActuatorDestroy(&ra);
    return 1;
  }
  /* --stride: keep snapshots 0, K, 2K, ... (compacted in place) */
  const int ns_all = ns;
  ns = 0;
  for (int k = 0; k < ns_all; k += stride, ns++) {
    memmove(q + (size_t)ns * n, q + (size_t)k * n, (size_t)n * sizeof(double));
    memmove(p + 12 * (size_t)ns, p + 12 * (size_t)k, 12 * sizeof(double));
    memmove(g + 3 * (size_t)ns, g + 3 * (size_t)k, 3 * sizeof(double));
    memmove(F + 3 * (size_t)ns, F + 3 * (size_t)k, 3 * sizeof(double));
  }
  const int cnt[CSF_ROM_NSET] = {ra.fe.mesh->ntet, ra.fe.model->nfib, ra.fe.mesh->nface};
  static const char* const kName[CSF_ROM_NSET] = {"/A_tet", "/A_fibre", "/A_face"};
  csH5File* f = cs_h5Create(out, &err);
  int rc = f ? 0 : 1;
  /* the bodies and the fibres; the chambers' faces are in closed form (csf_romChamberTensors:
   * exact), so the face set is not fitted */
  for (int s = 0; s < CSF_ROM_SET_FACE && rc == 0; s++) {
    if (only >= 0 && s != only) {
      continue;
    }
    const int wd = csf_romElementForcesWidth(ra.rom, (csfRomSet)s);
    const size_t rows = (size_t)ns * (size_t)wd, cols = (size_t)cnt[s];
    double* A = malloc(rows * cols * sizeof(double));
    double* G = malloc(cols * (size_t)wd * sizeof(double));
    if (!A || !G) {
      fprintf(stderr, "crawlsim rom: out of memory (%zu x %zu)\n", rows, cols);
      rc = 1;
    }
    for (int k = 0; k < ns && rc == 0; k++) {
      memcpy(ra.d->q, q + (size_t)k * n, (size_t)n * sizeof(double));
      csfRomLoad ld;
      csf_romActuatorLoad(&ra, p + 12 * (size_t)k, g + 3 * (size_t)k, F + 3 * (size_t)k, &ld);
      if (csf_romElementForces(ra.rom, ra.d, &ld, (csfRomSet)s, G) != 0) {
        fprintf(stderr, "crawlsim rom: snapshot %d: an element inverts at its projection\n", k);
        rc = 1;
        break;
      }
      for (size_t e = 0; e < cols; e++) {
        for (int j = 0; j < wd; j++) {
          A[((size_t)k * wd + j) * cols + e] = G[e * (size_t)wd + j];
        }
      }
    }
    const size_t dims[2] = {rows, cols};
    if (rc == 0 && cs_h5WriteDoubles(f, kName[s], 2, dims, A, &err) != CS_OK) {
      fprintf(stderr, "crawlsim rom: %s\n", err.msg);
      rc = 1;
    }
    free(A), free(G);
  }
  /* the mixed model's pressure matrix A = sum_e w_e (V_e / kappa) P_e P_e^T, per element (its
   * lower triangle, mm^3/MPa; constant in q): weights fitted to it as well keep p^ = A^-1 b */
  const int mp = ra.rom->m;
  if (mp > 0 && rc == 0 && only != CSF_ROM_SET_FIBRE) {
    rc = writeOuterRows(f, "/A_tet_pressure", cnt[0], mp, ra.rom->P, ra.fe.model->vol, NULL,
                        1.0 / ra.fe.model->mat.kappa);
  }
  /* the fibre projection matrix G = sum_f W_f Q_f Q_f^T, per fibre (its lower triangle, N;
   * constant in q): weights fitted to it keep E^ and S* (fem/fem_rom_fibre.h) */
  const int mf = ra.rom->mf;
  if (mf > 0 && rc == 0 && only != CSF_ROM_SET_TET) {
    rc = writeOuterRows(f, "/A_fibre_projection", cnt[1], mf, ra.rom->Qf, ra.fe.model->fib_EA,
                        ra.fe.model->fib_L0, 1.0);
  }
  if (f) {
    cs_h5AttrDouble(f, "/", "m", mp, &err);
    cs_h5AttrDouble(f, "/", "mf", mf, &err);
    cs_h5AttrString(f, "/", "format", "crawlsim-rom-ecsw-matrix 1", &err);
    cs_h5AttrString(f, "/", "basis", basis, &err);
    cs_h5AttrDouble(f, "/", "n", n, &err);
    cs_h5AttrDouble(f, "/", "nsnap", ns, &err);
    cs_h5AttrDouble(f, "/", "stride", stride, &err);
    if (cs_h5CloseChecked(f, &err) != CS_OK && rc == 0) {
      fprintf(stderr, "crawlsim rom: %s\n", err.msg);
      rc = 1;
    }
  }
  if (rc == 0) {
    printf("crawlsim rom: ecsw-matrix: %d snapshots (of %d, stride %d) x %d coordinates (%d "
           "pressure modes, %d fibre strain modes) over %d Tet10 and %d fibre elements (%s) "
           "-> %s\n", ns, ns_all, stride, n, mp, mf, cnt[0], cnt[1],
           only < 0 ? "both sets" : only == 0 ? "the Tet10s only" : "the fibres only", out);
  }
  free(q), free(p), free(g), free(F);
  csf_romActuatorDestroy(&ra);
  return rc;
}
