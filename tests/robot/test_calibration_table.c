/* test_calibration_table.c: the FE mode table reader (robot_calibration_table.h) accepts a
 * well-formed table and refuses every defective one through csr_calibrationOpen with one line
 * naming the file and the cause: a missing mode case, another actuator, a truncated dataset, a
 * NaN, a decreasing or non-zero-first pressure, an unfinished case (no status, or a status that
 * is not "complete"/"ended at ..."), p_end not the last row, another format version, missing FE
 * settings, an unknown kind, ratios out of range, a missing dataset, a negative stiffness and a
 * probe off the sweep's rows; variable-length (h5py) strings are read as fixed ones. Each
 * defect is made by changing one thing in a good synthetic table (test_calibration_synth.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_calibration.h"
#include "test_calibration_synth.h"

/* a smooth, symmetric truth: Ω1 alone bends 1.2 rad/MPa towards Ω3, linear in each chamber */
static void truthLinear(const void* ctx, int seg, const double p[4], double bend[2],
                        double* stretch, double* radial, double* radmax) {
  (void)ctx, (void)seg;
  const double g1 = 1.2 * (p[0] - p[2]), g2 = 1.2 * (p[1] - p[3]);
  bend[0] = -(g1 + g2) / sqrt(2.0);
  bend[1] = -(g1 - g2) / sqrt(2.0);
  *stretch = 1 + 0.02 * (p[0] + p[1] + p[2] + p[3]);
  *radial = 0.004 * (p[0] + p[1] + p[2] + p[3]);
  *radmax = 0.3 * (p[0] + p[1] + p[2] + p[3]);
}

static void stiffLinear(const void* ctx, int seg, double pbar, double* EI, double* EA) {
  (void)ctx;
  *EI = (3000 + 100 * seg) * (1 + pbar);
  *EA = 200 * (1 + 2 * pbar);
}

static const char* const kGood = "caltab_good.h5";
static const char* const kBad = "caltab_bad.h5";


static void legActuator(csrActuator* act) {
  csError err;
  CS_EXPECT(csr_actuatorPreset(act, "leg", &err) == CS_OK);
}


/* write the good table to `path` */
static void writeGood(const char* path, const csrActuator* leg) {
  SynthSpec sp = {truthLinear, stiffLinear, NULL, 0.05, 0, 0, 0};
  synthWrite(path, leg, &sp);
}


static void test_good_table_opens_as_mode_table(void) {
  csrActuator leg;
  legActuator(&leg);
  writeGood(kGood, &leg);
  CS_EXPECT(csr_calTableIsModeTable(kGood));
  csError err;
  csrCalibration* c = csr_calibrationOpen(kGood, &leg, &err);
  CS_EXPECT(c != NULL);
  if (!c) {
    fprintf(stderr, "  %s\n", err.msg);
    return;
  }
  csrBendMap map = csr_calibrationMap(c);
  CS_EXPECT(strstr(map.name, "FE mode table") != NULL && strstr(map.name, kGood) != NULL);
  /* the range is the modes' (0.5 MPa); the held-out cases' shorter sweeps do not limit it */
  CS_EXPECT_NEAR(map.p_max, 0.5, 1e-15, 0);
  const csrCalTable* t = csr_calibrationTable(c);
  CS_EXPECT(t != NULL && t->ncase == SYNTH_NCASE);
  CS_EXPECT(t && !strcmp(t->fe_fibre_law, "tension-only"));
  CS_EXPECT(csr_calibrationModel(c) != NULL);
  /* the table's cases are found by chamber pattern and kind */
  const double h1[4] = {1, 1.0 / 3.0, 0, 0};
  const csrCalCase* h = t ? csr_calTableFind(t, CSR_CAL_HOLDOUT, h1) : NULL;
  CS_EXPECT(h != NULL && !strcmp(h->name, "H1") && h->m == 7 && h->complete);
  CS_EXPECT(t && csr_calTableFind(t, CSR_CAL_MODE, h1) == NULL);
  csr_calibrationClose(c);
}


/* make kBad = kGood with one defect applied by `fn`, then expect the refusal */
typedef void (*Defect)(const char* path);

static void copyGood(void) {
  FILE* in = fopen(kGood, "rb");
  FILE* out = fopen(kBad, "wb");
  CS_EXPECT(in && out);
  char buf[8192];
  size_t n;
  while (in && out && (n = fread(buf, 1, sizeof buf, in)) > 0) {
    fwrite(buf, 1, n, out);
  }
  if (in) fclose(in);
  if (out) fclose(out);
}

static void dropO13(const char* p) { synthDelete(p, "/cases/O13"); }
static void otherS1(const char* p) { synthSetDouble(p, "/", "S1", 40); }
static void truncBend(const char* p) { synthTruncate(p, "/cases/O12/bend"); }
static void nanStretch(const char* p) { synthPoke(p, "/cases/O124/stretch", 3 * 4 + 1, NAN); }
static void downPressure(const char* p) { synthPoke(p, "/cases/O1/pressure", 3, 0.1); }
static void firstPressure(const char* p) { synthPoke(p, "/cases/O1/pressure", 0, 0.01); }
static void noStatus(const char* p) { synthDeleteAttr(p, "/cases/H2", "status"); }
static void runStatus(const char* p) { synthSetString(p, "/cases/O12r05", "status", "running"); }
static void pEnd(const char* p) { synthSetDouble(p, "/cases/O1234", "p_end", 0.45); }
static void format2(const char* p) {
  synthSetString(p, "/", "format", "crawlsim-fe-calibration 2");
}
static void noMesh(const char* p) { synthDeleteAttr(p, "/", "fe_mesh_size_mm"); }
static void badLaw(const char* p) { synthSetString(p, "/", "fe_fibre_law", "elastic"); }
static void badMesh(const char* p) { synthSetDouble(p, "/", "fe_mesh_symmetric", 0.5); }
static void badKind(const char* p) { synthSetString(p, "/cases/O2", "kind", "fitted"); }
static void badRatio(const char* p) { synthSetDouble(p, "/cases/O1", "ratio2", 1.5); }
static void noRadial(const char* p) { synthDelete(p, "/cases/O12O34r3/radial"); }
static void negEI(const char* p) { synthPoke(p, "/cases/O1234/EI", 6 * 1 + 2 * 2, -5); }
static void offRow(const char* p) { synthPoke(p, "/cases/O12/probe_pressure", 1, 0.125); }
static void nanTip(const char* p) { synthPoke(p, "/cases/H3/tip", 3 * 2 + 0, INFINITY); }
static void shortEA(const char* p) { synthTruncate(p, "/cases/O12/EA"); }
static void negForce(const char* p) { synthPoke(p, "/cases/O12/probe_force", 3 * 1 + 2, -0.05); }


static void test_every_bad_table_is_refused(void) {
  csrActuator leg;
  legActuator(&leg);
  writeGood(kGood, &leg);
  const struct {
    Defect fn;
    const char* want;
  } kDefects[] = {
      {dropO13, "has no finished mode case O13 (chambers at 1:0:1:0)"},
      {otherS1, "calibrated for another actuator: S1 = 40 in the table, 50 in the leg"},
      {truncBend, "case O12: dataset 'bend' has shape [10,3,2], expected [11,3,2] (M = 11 "
                  "rows): truncated or inconsistent"},
      {nanStretch, "case O124: stretch row 5 segment 2 is nan (not finite)"},
      {downPressure, "case O1: pressure row 4 (0.1 MPa) must be above row 3 (0.1 MPa)"},
      {firstPressure, "case O1: pressure row 1 is 0.01 MPa (a sweep starts at 0)"},
      {noStatus, "case H2 is unfinished (no status attribute)"},
      {runStatus, "case O12r05 is unfinished (status 'running')"},
      {pEnd, "case O1234: p_end is 0.45 MPa but the last row is at 0.5 MPa"},
      {format2, "format 'crawlsim-fe-calibration 2' is not supported"},
      {noMesh, "no FE setting 'fe_mesh_size_mm'"},
      {badLaw, "fe_fibre_law must be \"linear\" or \"tension-only\""},
      {badMesh, "fe_mesh_symmetric must be 0 or 1"},
      {badKind, "case O2: unknown kind 'fitted'"},
      {badRatio, "case O1: ratio2 is 1.5 (chamber ratios are in [0, 1])"},
      {noRadial, "case O12O34r3 has no dataset 'radial'"},
      {negEI, "case O1234: EI probe 2 segment 3 is -5 (a stiffness must be > 0"},
      {negForce, "case O12: probe_force row 2 is -0.05 N (must be in 0..1e12)"},
      {offRow, "case O12: probe 2 at 0.125 MPa is not a row of the sweep"},
      {nanTip, "case H3: tip row 3 component 1 is inf (not finite)"},
      {shortEA, "case O12: dataset 'EA' has shape [3,3], expected [4,3] (K = 4 rows)"},
  };
  for (size_t k = 0; k < sizeof kDefects / sizeof kDefects[0]; k++) {
    copyGood();
    kDefects[k].fn(kBad);
    expectRefused(kBad, &leg, kDefects[k].want);
  }
  /* a case that ended early at a limit point is finished: its range ends there */
  copyGood();
  synthSetString(kBad, "/cases/O13", "status",
                 "ended at 0.5 MPa: pressure limit point at 0.4 MPa");
  synthSetDouble(kBad, "/cases/O13", "p_limit", 0.4);
  csError err;
  csrCalibration* c = csr_calibrationOpen(kBad, &leg, &err);
  CS_EXPECT(c != NULL);
  if (c) {
    csrBendMap map = csr_calibrationMap(c);
    CS_EXPECT_NEAR(map.p_max, 0.4, 1e-15, 0);
    CS_EXPECT(strstr(map.name, "range ended by O13") != NULL);
    const double p[4] = {0.41, 0, 0, 0};
    double bend[2], stretch;
    CS_EXPECT(map.eval(map.ctx, 0, p, bend, &stretch) == CSR_MAP_OUT_OF_RANGE);
  }
  csr_calibrationClose(c);
  /* a table written before the fibre law was recorded is of the linear law */
  copyGood();
  synthDeleteAttr(kBad, "/", "fe_fibre_law");
  c = csr_calibrationOpen(kBad, &leg, &err);
  CS_EXPECT(c != NULL && !strcmp(csr_calibrationTable(c)->fe_fibre_law, "linear"));
  csr_calibrationClose(c);
  /* strings as h5py writes them (variable length, UTF-8) read like the writer's fixed ones */
  copyGood();
  synthSetVlenString(kBad, "/", "format", "crawlsim-fe-calibration 1");
  synthSetVlenString(kBad, "/cases/O1", "kind", "mode");
  synthSetVlenString(kBad, "/cases/O1", "status", "complete");
  c = csr_calibrationOpen(kBad, &leg, &err);
  CS_EXPECT(c != NULL);
  csr_calibrationClose(c);
  remove(kBad);
  remove(kGood);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_good_table_opens_as_mode_table);
  CS_RUN(test_every_bad_table_is_refused);
  return cs_testSummary();
}
