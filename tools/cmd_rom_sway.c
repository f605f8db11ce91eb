/* cmd_rom_sway.c: `crawlsim rom sway`: the sway-buckling load of the leg in the Earth stance's
 * pose by the rod, the reduced model of a leg file and the full FE (issue 34; the procedure is
 * actuator/robot_sway.h's, the compliances robot_rod.h csr_rodSwayCompliance and
 * fem/fem_rom_sway.h).
 *
 * The pose the stance check assumes (core/sim_model.h cs_modelStanceCheck): the straight,
 * unpressurised leg, clamped at the hip, its foot loaded by a dead axial force P and free to
 * sway but not to turn; gravity off (the check's load is the stance's share of the robot's
 * weight at the foot). At each axial load of --load, ascending: the foot's compliance C and
 * from it the clamped-free stiffness 1 / c11 and the guided (sway) stiffness k_sway; the first
 * sign change of each, interpolated, is that model's buckling load (or extrapolated from the
 * last two loads, said so). The FE runs at the loads of --fe-load only, on the leg file's own
 * mesh and FE model (made whole: its sparse pattern and solver), its tangent factored by LDL^T
 * (the negative pivots count the buckling modes passed); with --fe-mesh-size on a mesh of its own
 * (gmsh), instead, to measure the FE's discretisation.
 * Output: a table on stdout and, with --out, a CSV (model, P_N, c11_mm_per_N, c12_per_N,
 * c22_per_Nmm, k_cantilever_N_per_mm, k_sway_N_per_mm, neg_pivots, newton, cpu_s, and the tip
 * face's mean displacement tip_x_mm, tip_y_mm, tip_z_mm of the rom's and the FE's states: a
 * lateral part is that model's own imperfection). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cmd_rom_common.h"
#include "cs_signal.h"
#include "fem_assembly.h"
#include "fem_rom_sway.h"
#include "robot_leg.h"
#include "robot_rod.h"
#include "robot_rom_file.h"
#include "robot_sway.h"

enum { SWAY_MAX_LOADS = 32 };

static const csxOpt kSwayOpts[] = {
    {"--leg-file", "LEG.h5", "none: the rod alone",
     "the reduced leg (crawlsim rom leg-file); its FE model serves --fe-load"},
    {"--load", "P", "0, 0.2, ..., 1.4",
     "an axial load on the foot in N, 0 .. 10, for the rod and the reduced model (repeatable, at "
     "most 32, ascending)"},
    {"--fe-load", "P", "none",
     "an axial load in N, 0 .. 10, for the full FE (repeatable, at most 32, ascending)"},
    {"--rod-elements", "N", "the rod's default (4)",
     "the rod's elements per segment, 1 .. 64 (its foot is the last element's frame: held flat, "
     "the column flexes over L - l_N / 2)"},
    {"--fe-mesh-size", "MM", "none: the leg file's mesh and FE model",
     "the FE of --fe-load meshed afresh by gmsh at this l_soft (symmetric mesh), 1 .. 20"},
    {"--fe-fibres", "0|1", "1",
     "with --fe-mesh-size: 0 leaves the fibres out (what they add to the section's stiffness)"},
    {"--work", "DIR", ".", "where gmsh's files of --fe-mesh-size are written"},
    {"--skip-rom", NULL, "off", "the reduced model not run (the rod and --fe-load only)"},
    {"--out", "FILE.csv", "none", "the rows as CSV"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kSwayTable = {
    "rom sway", "",
    "The foot's compliance of the straight leg under an axial dead load (hip clamped, gravity "
    "off) by the rod, the reduced model and the full FE, condensed to the guided (sway) "
    "stiffness with the foot held flat: its zero is the sway-buckling load of the Earth "
    "stance's check (pi^2 E'I / L^2), the clamped-free stiffness's zero the cantilever's.",
    kSwayOpts, CSX_NOPT(kSwayOpts), NULL};

static double cpuNow(void) {
  struct timespec c;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
  return (double)c.tv_sec + 1e-9 * (double)c.tv_nsec;
}

typedef struct SwayRows_ {
  FILE* csv;
  int n;
  double P[SWAY_MAX_LOADS], kc[SWAY_MAX_LOADS], ks[SWAY_MAX_LOADS];
} SwayRows;

/* the tip face's mean displacement (mm) of a solved state u: the straight column's is axial;
 * a lateral part is the model's own imperfection (a basis or mesh not quite symmetric) */
static void tipMean(const csfActuatorFE* fe, const double* u, double t[3]) {
  double w = 0;
  t[0] = t[1] = t[2] = 0;
  for (int a = 0; a < fe->mesh->nnode; a++) {
    const double wa = fe->tip_unit[3 * a];
    w += wa;
    for (int i = 0; i < 3; i++) {
      t[i] += wa * u[3 * a + i];
    }
  }
  for (int i = 0; i < 3; i++) {
    t[i] /= w > 0 ? w : 1.0;
  }
}

static void swayRow(SwayRows* rows, const char* model, double P, const double C[3], int neg,
                    int newton, double cpu, const double tip[3]) {
  const double kc = 1.0 / C[0], ks = csr_swayGuided(C[0], C[1], C[2]);
  printf("%-5s %7.3f %12.5g %12.5g %12.5g %12.5g %12.5g %4d %6d %8.1f %9.3g %9.3g %9.4g\n",
         model, P, C[0], C[1], C[2], kc, ks, neg, newton, cpu, tip[0], tip[1], tip[2]);
  fflush(stdout);
  if (rows->csv) {
    fprintf(rows->csv, "%s,%.6g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%.3f,%.6g,%.6g,%.6g\n", model, P,
            C[0], C[1], C[2], kc, ks, neg, newton, cpu, tip[0], tip[1], tip[2]);
    fflush(rows->csv);
  }
  rows->P[rows->n] = P, rows->kc[rows->n] = kc, rows->ks[rows->n] = ks;
  rows->n++;
}

static void swaySummary(const char* model, const SwayRows* rows) {
  int ec = 0, es = 0;
  const double pc = csr_swayZero(rows->n, rows->P, rows->kc, &ec);
  const double ps = csr_swayZero(rows->n, rows->P, rows->ks, &es);
  printf("crawlsim rom: sway: %s: cantilever buckling load %.4g N%s, sway-buckling load %.4g N%s\n",
         model, pc, ec ? " (extrapolated)" : "", ps, es ? " (extrapolated)" : "");
}

static int parseLoads(const char* flag, const char* v, double* list, int* n) {
  if (*n == SWAY_MAX_LOADS) {
    fprintf(stderr, "crawlsim rom: sway: more than %d %s options\n", SWAY_MAX_LOADS, flag);
    return 1;
  }
  if (csx_romParseNumber(flag, v, 0.0, 10.0, &list[*n])) {
    return 1;
  }
  if (*n > 0 && list[*n] <= list[*n - 1]) {
    fprintf(stderr, "crawlsim rom: sway: %s %s: the loads must ascend\n", flag, v);
    return 1;
  }
  (*n)++;
  return 0;
}

/* a whole number in [lo, hi] from option `flag`'s value; 1 after one error line */
static int parseWhole(const char* flag, const char* v, double lo, double hi, double* out) {
  if (csx_romParseNumber(flag, v, lo, hi, out)) {
    return 1;
  }
  if (*out != floor(*out)) {
    fprintf(stderr, "crawlsim rom: sway: %s '%s' must be a whole number\n", flag, v);
    return 1;
  }
  return 0;
}

/* the rod of the actuator (default parameters, no actuation: p = 0) at every load */
static csStatus swayRod(const csrActuator* act, int nel, const double* loads, int nl,
                        SwayRows* rows, csError* err) {
  csrRodParams par = csr_rodDefaultParams(act);
  par.elements_per_segment = nel > 0 ? nel : par.elements_per_segment;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = act;
  sp.params = &par;
  sp.frame[0] = sp.frame[4] = sp.frame[8] = 1.0;
  csrRodModel* m = csr_rodModelCreate(&sp, err);
  csrRodData* d = m ? csr_rodDataCreate(m, err) : NULL;
  double* y = m ? malloc((size_t)csr_rodStateSize(m) * sizeof(double)) : NULL;
  csStatus st = !m || !d ? err->status : !y ? cs_errorSet(err, CS_ERR_MEMORY, "rod sway: out "
                                                           "of memory") : CS_OK;
  const double L = csr_actuatorLength(act);
  for (int k = 0; k < nl && st == CS_OK; k++) {
    double C[3];
    const double c0 = cpuNow();
    /* perturbations small against the loads (the response's third order stays below 1e-8)
     * and large against the static tolerance */
    st = csr_rodSwayCompliance(m, d, loads[k], 1e-4, 1e-4 * L, y, C, err);
    if (st == CS_OK) {
      const double none[3] = {NAN, NAN, NAN};
      swayRow(rows, "rod", loads[k], C, -1, 0, cpuNow() - c0, none);
    }
  }
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
  return st;
}

/* the reduced model of a leg file, read without gmsh (as cmd_bend_rom.c's romFromFile) */
static csStatus openLegFile(const char* path, const csrActuator* act, csfRomActuator* ra,
                            csError* err) {
  csrRomLegFile lf;
  csStatus st = csr_romLegFileRead(path, &lf, err);
  if (st != CS_OK) {
    return st;
  }
  st = csr_romLegFileCheckActuator(&lf, path, act, err);
  if (st != CS_OK) {
    csr_romLegFileFree(&lf);
    return st;
  }
  csfMesh* me = lf.mesh;
  csfModel* m = lf.model;
  csfRom* rom = lf.rom;
  lf.mesh = NULL, lf.model = NULL, lf.rom = NULL;
  csr_romLegFileFree(&lf);
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  return csf_romActuatorFromModel(act, &spec, me, m, rom, path, ra, err);
}

/* the full FE of fe (a finalised model) at the loads fel, ascending, from its reference state */
static csStatus swayFE(csfActuatorFE* fe, const double* c_lat, const double* c_rot,
                       const double axis[3], const double* fel, int nfe, SwayRows* rows,
                       csError* err) {
  csfModel* m = fe->model;
  m->solver.max_threads = 1;
  csfData* d = csf_dataCreate(m, err);
  if (!d) {
    return err->status ? err->status : CS_ERR_MEMORY;
  }
  csfNewtonOptions no = csf_newtonDefault();
  no.threads = 1;
  no.max_iter = 40; /* as fem_bend.c's sweep: the slender leg crosses flat energy valleys */
  rows->n = 0;
  double Pfrom = 0.0;
  csStatus st = CS_OK;
  for (int k = 0; k < nfe && st == CS_OK && !*csx_signalFlag(); k++) {
    double C[3];
    int neg = -1, newton = 0;
    const double c0 = cpuNow();
    st = csf_feSwayCompliance(fe, d, &no, c_lat, c_rot, axis, Pfrom, fel[k], C, &neg, &newton,
                              err);
    if (st == CS_OK) {
      double t[3];
      tipMean(fe, d->u, t);
      swayRow(rows, "fe", fel[k], C, neg, newton, cpuNow() - c0, t);
      Pfrom = fel[k];
    }
  }
  if (st == CS_OK) {
    swaySummary("fe", rows);
  }
  csf_dataDestroy(d);
  return st;
}

/* the full FE meshed afresh (gmsh; the symmetric mesh of l_soft, every chamber tagged as the
 * snapshots' model) at the loads fel: a mesh other than the leg file's */
static csStatus swayFEMesh(const csrActuator* act, double l_soft, int fibres, const char* stem,
                           const double* fel, int nfe, SwayRows* rows, csError* err) {
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.fibres = fibres;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      spec.ratio[s][j] = 1.0;
    }
  }
  spec.mesh_size = l_soft;
  spec.mesh_symmetric = 1;
  spec.work_stem = stem;
  csfActuatorFE fe;
  memset(&fe, 0, sizeof fe);
  csStatus st = csf_actuatorFECreate(act, &spec, &fe, err);
  const int ndof = st == CS_OK ? fe.model->ndof : 0;
  double* c = st == CS_OK ? malloc(2 * (size_t)ndof * sizeof(double)) : NULL;
  if (st == CS_OK && !c) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "rom sway: out of memory (%d values)", 2 * ndof);
  }
  double axis[3];
  if (st == CS_OK) {
    printf("crawlsim rom: sway: FE mesh l_soft %g mm: %d Tet10, %d dofs, %d fibre elements%s\n",
           l_soft, fe.mesh->ntet, ndof, fe.model->nfib, fibres ? "" : " (fibres off)");
    st = csf_swayFunctionals(&fe, c, c + ndof, axis, err);
  }
  if (st == CS_OK) {
    st = swayFE(&fe, c, c + ndof, axis, fel, nfe, rows, err);
  }
  free(c);
  csf_actuatorFEDestroy(&fe);
  return st;
}

static csStatus swayModels(const csrActuator* act, int rod_nel, const char* leg,
                           const double* loads, int nl, int skip_rom, const double* fel,
                           int nfe, double fe_mesh, int fe_fibres, const char* stem, FILE* csv,
                           csError* err) {
  printf("%-5s %7s %12s %12s %12s %12s %12s %4s %6s %8s %9s %9s %9s\n", "model", "P (N)",
         "c11 (mm/N)", "c12 (1/N)", "c22", "k_cant", "k_sway", "neg", "newton", "cpu (s)",
         "tip x", "tip y", "tip z");
  SwayRows rows = {csv, 0, {0}, {0}, {0}};
  csStatus st = swayRod(act, rod_nel, loads, nl, &rows, err);
  if (st != CS_OK) {
    return st;
  }
  swaySummary("rod", &rows);
  if (nfe > 0 && !isnan(fe_mesh)) {
    st = swayFEMesh(act, fe_mesh, fe_fibres, stem, fel, nfe, &rows, err);
  }
  if (!leg || st != CS_OK) {
    return st;
  }
  csfRomActuator ra;
  memset(&ra, 0, sizeof ra);
  st = openLegFile(leg, act, &ra, err);
  const int ndof = st == CS_OK ? ra.fe.model->ndof : 0;
  double* c = st == CS_OK ? malloc(2 * (size_t)ndof * sizeof(double)) : NULL;
  double axis[3];
  if (st == CS_OK && !c) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "rom sway: out of memory (%d values)", 2 * ndof);
  }
  if (st == CS_OK) {
    st = csf_swayFunctionals(&ra.fe, c, c + ndof, axis, err);
  }
  rows.n = 0;
  for (int k = 0; k < nl && !skip_rom && st == CS_OK && !*csx_signalFlag(); k++) {
    double C[3];
    const double c0 = cpuNow();
    const long it0 = ra.n_newton;
    st = csf_romSwayCompliance(&ra, c, c + ndof, axis, loads[k], C, err);
    if (st == CS_OK) {
      double t[3];
      tipMean(&ra.fe, ra.u, t);
      swayRow(&rows, "rom", loads[k], C, -1, (int)(ra.n_newton - it0), cpuNow() - c0, t);
    }
  }
  if (st == CS_OK && nl > 0 && !skip_rom) {
    swaySummary("rom", &rows);
  }
  if (st == CS_OK && nfe > 0 && isnan(fe_mesh)) {
    /* the leg file's model made whole for the FE's solvers: the same mesh, fibres and clamp */
    st = csf_modelFinalize(ra.fe.model, err);
    if (st == CS_OK) {
      st = swayFE(&ra.fe, c, c + ndof, axis, fel, nfe, &rows, err);
    }
  }
  free(c);
  csf_romActuatorDestroy(&ra);
  return st;
}

int csx_cmdRomSway(int argc, char** argv) {
  csx_signalInstall();
  const char* leg = NULL, *out = NULL, *actname = "leg";
  const char* sets[CSX_ROM_MAX_SETS];
  int nset = 0, nl = 0, nfe = 0;
  double rod_nel = 0, fe_mesh = NAN, fe_fibres = 1;
  const char* work = ".";
  int skip_rom = 0;
  double loads[SWAY_MAX_LOADS], fel[SWAY_MAX_LOADS];
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kSwayTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kSwayTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kSwayTable, it.value);
    }
    const char* v = it.value;
    int bad = 0;
    if (csx_optIs(it.opt, "--leg-file")) {
      leg = v;
    } else if (csx_optIs(it.opt, "--out")) {
      out = v;
    } else if (csx_optIs(it.opt, "--load")) {
      bad = parseLoads("--load", v, loads, &nl);
    } else if (csx_optIs(it.opt, "--fe-load")) {
      bad = parseLoads("--fe-load", v, fel, &nfe);
    } else if (csx_optIs(it.opt, "--fe-mesh-size")) {
      bad = csx_romParseNumber("--fe-mesh-size", v, 1, 20, &fe_mesh);
    } else if (csx_optIs(it.opt, "--fe-fibres")) {
      bad = parseWhole("--fe-fibres", v, 0, 1, &fe_fibres);
    } else if (csx_optIs(it.opt, "--work")) {
      work = v;
    } else if (csx_optIs(it.opt, "--skip-rom")) {
      skip_rom = 1;
    } else if (csx_optIs(it.opt, "--rod-elements")) {
      bad = parseWhole("--rod-elements", v, 1, 64, &rod_nel);
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--set")) {
      bad = csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS);
    }
    if (bad) {
      return 1;
    }
  }
  if (nl == 0) {
    for (int k = 0; k < 8; k++) {
      loads[nl++] = 0.2 * k;
    }
  }
  if (nfe > 0 && !leg && isnan(fe_mesh)) {
    fprintf(stderr, "crawlsim rom: sway: --fe-load needs --leg-file (its FE model) or "
            "--fe-mesh-size\n");
    return 1;
  }
  csrActuator act;
  if (csx_romActuator(actname, sets, nset, 1, &act)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csStatus st = CS_OK;
  FILE* csv = NULL;
  if (st == CS_OK && out) {
    csv = fopen(out, "w");
    if (!csv) {
      fprintf(stderr, "crawlsim rom: sway: %s: cannot be written\n", out);
      return 1;
    }
    fprintf(csv, "model,P_N,c11_mm_per_N,c12_per_N,c22_per_Nmm,k_cantilever_N_per_mm,"
            "k_sway_N_per_mm,neg_pivots,newton,cpu_s,tip_x_mm,tip_y_mm,tip_z_mm\n");
  }
  if (st == CS_OK) {
    const double EI = 8.0 * act.C10 * csr_legSectionI(&act), L = csr_actuatorLength(&act);
    printf("crawlsim rom: sway: closed forms (E'I = 8 C10 I = %.4g N mm^2, L = %.4g mm): "
           "sway-buckling pi^2 E'I / L^2 = %.4g N, cantilever %.4g N\n", EI, L,
           csr_swayEuler(EI, L), csr_cantileverEuler(EI, L));
    char stem[620];
    snprintf(stem, sizeof stem, "%.500s/sway_mesh", work);
    st = swayModels(&act, (int)rod_nel, leg, loads, nl, skip_rom, fel, nfe, fe_mesh,
                    (int)fe_fibres, stem, csv, &err);
  }
  if (csv && fclose(csv) != 0 && st == CS_OK) {
    st = cs_errorSet(&err, CS_ERR_IO, "%s: write failed", out);
  }
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: sway: %s\n", err.msg);
    return 1;
  }
  return 0;
}
