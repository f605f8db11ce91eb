/* test_levels_cli.c: `crawlsim run --legs auto --tol MM` end to end, on the shipped table
 * robot/levels.csv (tools/bench_levels.py's measurements). For both paper scenes:
 *  - a loose tolerance (the scene's largest measured error) picks a cheaper configuration than
 *    a tight one (its smallest): a property of the measured data, so this fails if the table
 *    stops showing a trade-off;
 *  - the configuration recorded in the output (leg_model, links_per_segment, step_s,
 *    macro_step_s, rod_tolerance_scale, leg_step_order, leg_step_adaptive, leg_step_tol_mm) is
 *    the one the banner and legs_auto_choice name, and the one the table says is cheapest
 *    within the tolerance (computed here, independently of the picker); the run file's
 *    track_error_mm is that row's error;
 *  - `--strain-step adaptive` / `fixed` beside it picks the cheapest row of that step kind (an
 *    adaptive row runs the adaptive step at its tolerance, dt its longest step), and a table
 *    without rows of the kind is one error;
 *  - a tolerance below the best error is one error line naming the best achievable error;
 *  - every row's whole run is judged, and a row whose whole run fails is never picked;
 *  - the table holds at least two configurations of every registered level per scene, and the
 *    benchmark's full table docs/levels_bench.csv has rows of every task and level.
 * And a bad or missing table, a missing --tol and a stray --tol are one-line errors before
 * anything runs. argv[1] is the crawlsim executable. */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"
#include "robot_leg.h"
#include "robot_levels.h"

static const char* exe_path = NULL;
static char g_table[1024];
static csrLevelTable g_t;


/* the scene's cheapest row within tol (ties: smaller error) of a step kind (0 any, 1 fixed, 2
 * adaptive), computed from the rows */
static int cheapestKindWithin(const char* scene, double tol, int kind) {
  int best = -1;
  for (int i = 0; i < g_t.nrow; i++) {
    const csrLevelRow* r = &g_t.row[i];
    if (strcmp(r->scene, scene) || r->error_mm > tol || r->whole_run == 0 ||
        (kind && (kind == 2) != (r->step_tol_mm > 0))) {
      continue;
    }
    if (best < 0 || r->cpu_s_per_s < g_t.row[best].cpu_s_per_s ||
        (r->cpu_s_per_s == g_t.row[best].cpu_s_per_s && r->error_mm < g_t.row[best].error_mm)) {
      best = i;
    }
  }
  return best;
}


static int cheapestWithin(const char* scene, double tol) {
  return cheapestKindWithin(scene, tol, 0);
}


/* run the scene with --legs auto --tol tol (and `extra`); check that row k ran and was
 * recorded */
static void expectRunsWith(const char* scene, double tol, const char* extra, int k) {
  const csrLevelRow* r = &g_t.row[k];
  char args[2048], out[64];
  snprintf(out, sizeof out, "levelscli_%s.h5", scene);
  snprintf(args, sizeof args, "run --scene %s --legs auto --tol %.17g --t-end 0.02 %s --out %s",
           scene, tol, extra, out);
  csCliResult res;
  cs_cliRun(exe_path, args, "levelscli", &res);
  CS_EXPECT(res.status == 0);
  char want[256];
  char tolnote[128] = "";
  if (r->rod_tol != 1) {
    snprintf(tolnote, sizeof tolnote, ", rod tol %g", r->rod_tol);
  }
  if (r->step_order > 0) {
    snprintf(tolnote + strlen(tolnote), sizeof tolnote - strlen(tolnote), ", step order %d",
             r->step_order);
  }
  if (r->step_tol_mm > 0) {
    snprintf(tolnote + strlen(tolnote), sizeof tolnote - strlen(tolnote), ", adaptive step at "
             "%g mm per step (dt its longest)", r->step_tol_mm);
  }
  snprintf(want, sizeof want, "--legs auto picked %s, links %d, macro steps %d, dt %g s%s:",
           r->level, r->links, r->macro_steps, r->dt_s, tolnote);
  CS_EXPECT(strstr(res.err, want) != NULL);
  snprintf(want, sizeof want, "legs %s,", r->level); /* the first banner line */
  CS_EXPECT(strstr(res.err, want) != NULL);
  printf("  %s, --tol %g mm%s%s: %s links %d macro %d step tol %g mm (%.3g mm, %.3g CPU s/s)\n",
         scene, tol, extra[0] ? " " : "", extra, r->level, r->links, r->macro_steps,
         r->step_tol_mm, r->error_mm, r->cpu_s_per_s);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(out, H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    char level[32] = "", choice[1100] = "";
    double links = 0, h = 0, H = 0, t = 0;
    CS_EXPECT(H5LTget_attribute_string(f, "/", "leg_model", level) >= 0);
    CS_EXPECT(!strcmp(level, r->level));
    CS_EXPECT(H5LTget_attribute_double(f, "/", "links_per_segment", &links) >= 0);
    CS_EXPECT(links == r->links);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "step_s", &h) >= 0 && h == r->dt_s);
    if (!strcmp(r->level, "rod")) {
      /* the row's --rod-tol is the run's */
      double k = 0;
      CS_EXPECT(H5LTget_attribute_double(f, "/", "rod_tolerance_scale", &k) >= 0 &&
                k == r->rod_tol);
    }
    if (r->step_order > 0) {
      /* the row's --step-order is the run's tree step */
      double o = 0;
      CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_order", &o) >= 0 &&
                o == r->step_order);
    }
    if (strcmp(r->level, "rod")) {
      /* a tree-stepped level: the row's step kind and tolerance are the run's */
      double adaptive = -1, stol = -1;
      CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_adaptive", &adaptive) >= 0 &&
                adaptive == (r->step_tol_mm > 0));
      if (r->step_tol_mm > 0) {
        CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_tol_mm", &stol) >= 0 &&
                  stol == r->step_tol_mm);
      }
    }
    /* the row's error is the run's recorded track error */
    double te = -1;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "track_error_mm", &te) >= 0 && te == r->error_mm);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "macro_step_s", &H) >= 0);
    CS_EXPECT_NEAR(H, r->dt_s * r->macro_steps, 1e-15, 1e-12);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "legs_auto_tol_mm", &t) >= 0 && t == tol);
    hsize_t dims[1] = {0};
    H5T_class_t cls;
    size_t sz = 0;
    CS_EXPECT(H5LTget_attribute_info(f, "/", "legs_auto_choice", dims, &cls, &sz) >= 0 &&
              sz < sizeof choice);
    if (sz < sizeof choice) {
      CS_EXPECT(H5LTget_attribute_string(f, "/", "legs_auto_choice", choice) >= 0);
    }
    CS_EXPECT(strstr(res.err, choice) != NULL && choice[0]); /* the banner says the same */
    H5Fclose(f);
  }
  remove(out);
  snprintf(out, sizeof out, "levelscli_%s.xdmf", scene);
  remove(out);
}


static void expectRuns(const char* scene, double tol, int k) {
  expectRunsWith(scene, tol, "", k);
}


/* exit 1, exactly one stderr line containing want, no output file */
static void expectError(const char* args, const char* want) {
  remove("levelscli_bad.h5");
  char full[2048];
  snprintf(full, sizeof full, "run --quiet --t-end 0.01 --out levelscli_bad.h5 %s", args);
  csCliResult res;
  cs_cliRun(exe_path, full, "levelscli", &res);
  CS_EXPECT(res.status == 1);
  CS_EXPECT(cs_cliOneLine(res.err));
  CS_EXPECT(strstr(res.err, want) != NULL);
  CS_EXPECT(!cs_cliFileExists("levelscli_bad.h5"));
  if (res.status != 1 || !strstr(res.err, want)) {
    printf("  %s -> %d: %s", args, res.status, res.err);
  }
}


static void test_levels_shipped_table_loose_cheaper_than_tight_on_both_scenes(void) {
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTableRead(g_table, &g_t, &err) == CS_OK);
  if (g_t.nrow == 0) {
    printf("  %s\n", err.msg);
    return;
  }
  const char* scenes[2] = {"flat-road", "obstacle"};
  for (int s = 0; s < 2; s++) {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < g_t.nrow; i++) {
      if (!strcmp(g_t.row[i].scene, scenes[s]) && g_t.row[i].whole_run != 0) {
        lo = fmin(lo, g_t.row[i].error_mm);
        hi = fmax(hi, g_t.row[i].error_mm);
      }
    }
    CS_EXPECT(isfinite(lo)); /* the table measures the scene */
    if (!isfinite(lo)) {
      continue;
    }
    /* the benchmark measured every registered level on the scene */
    for (int k = 0; k < csr_legTypeCount(); k++) {
      if (csr_legTypeAt(k)->needs_file) {
        continue; /* rom: measured only where a leg file is given (docs/notes/rom.md) */
      }
      int n = 0;
      for (int i = 0; i < g_t.nrow; i++) {
        n += !strcmp(g_t.row[i].scene, scenes[s]) && !strcmp(g_t.row[i].level,
                                                             csr_legTypeAt(k)->name);
      }
      CS_EXPECT(n >= 2); /* at least two resolutions of each */
      if (n < 2) {
        printf("  %s: %d rows of level %s\n", scenes[s], n, csr_legTypeAt(k)->name);
      }
    }
    int loose = cheapestWithin(scenes[s], hi), tight = cheapestWithin(scenes[s], lo);
    CS_EXPECT(g_t.row[loose].cpu_s_per_s < g_t.row[tight].cpu_s_per_s);
    expectRuns(scenes[s], hi, loose);
    expectRuns(scenes[s], lo, tight);
    /* below the best: one error naming the best achievable error */
    char args[256], want[128];
    snprintf(args, sizeof args, "--scene %s --legs auto --tol %.17g", scenes[s], 0.5 * lo);
    snprintf(want, sizeof want, "the best achievable is %.3g mm", lo);
    expectError(args, want);
  }
}


/* --strain-step beside --legs auto: the cheapest row of that step kind within the tolerance
 * (the shipped table holds both kinds on both scenes: the adaptive step is the strain level's
 * default); a loose tolerance would pick a fixed step where the adaptive one is asked */
static void test_levels_strain_step_picks_its_kind(void) {
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTableRead(g_table, &g_t, &err) == CS_OK);
  const char* scenes[2] = {"flat-road", "obstacle"};
  for (int s = 0; g_t.nrow > 0 && s < 2; s++) {
    double hi = -INFINITY;
    for (int i = 0; i < g_t.nrow; i++) {
      if (!strcmp(g_t.row[i].scene, scenes[s])) {
        hi = fmax(hi, g_t.row[i].error_mm);
      }
    }
    const int any = cheapestKindWithin(scenes[s], hi, 0);
    const int fixed = cheapestKindWithin(scenes[s], hi, 1);
    const int adaptive = cheapestKindWithin(scenes[s], hi, 2);
    CS_EXPECT(any >= 0 && fixed >= 0 && adaptive >= 0);
    if (fixed < 0 || adaptive < 0) {
      continue;
    }
    CS_EXPECT(g_t.row[adaptive].step_tol_mm > 0 && g_t.row[fixed].step_tol_mm == 0);
    expectRunsWith(scenes[s], hi, "--strain-step adaptive", adaptive);
    expectRunsWith(scenes[s], hi, "--strain-step fixed", fixed);
  }
  /* a table without adaptive rows: --strain-step adaptive beside auto is one error */
  CS_EXPECT(cs_cliWriteText("levelscli_fixed.csv",
                            "scene,level,links,macro_steps,dt_s,rod_tol,step_order,error_mm,"
                            "cpu_s_per_s,wall_s_per_s,machine\n"
                            "flat-road,strain,2,1,0.005,1,1,2,0.3,0.3,m\n"));
  expectError("--legs auto --tol 10 --levels levelscli_fixed.csv --strain-step adaptive",
              "no row for scene 'flat-road' with the adaptive step");
  remove("levelscli_fixed.csv");
  expectError("--legs auto --tol 10 --step-tol 5e-4", "--legs auto sets --links");
}


/* whole_run (format 5): the shipped table judges every row's whole run of its scene; a row
 * accurate on its window whose whole run fails (the obstacle's fixed-step BDF2, within 1 mm
 * over the first 4 s, falls off the step at 12 s) is never picked: at its own error the pick
 * is the cheapest row that does not fail, and the banner and run file say what was passed over.
 * A synthetic table where only failing rows meet the tolerance is one error naming them. */
static void test_levels_failing_whole_run_never_picked(void) {
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTableRead(g_table, &g_t, &err) == CS_OK);
  int judged = 0, passed = 0;
  for (int i = 0; i < g_t.nrow; i++) {
    judged += g_t.row[i].whole_run != -1;
  }
  CS_EXPECT(g_t.nrow > 0 && judged == g_t.nrow);
  for (int i = 0; i < g_t.nrow; i++) {
    const csrLevelRow* f = &g_t.row[i];
    if (f->whole_run != 0) {
      continue;
    }
    const int k = cheapestWithin(f->scene, f->error_mm);
    if (k < 0 || !(f->cpu_s_per_s < g_t.row[k].cpu_s_per_s) || passed++) {
      continue; /* one such run is enough: each takes a process */
    }
    char args[256];
    snprintf(args, sizeof args, "run --scene %s --legs auto --tol %.17g --t-end 0.01 --out "
             "levelscli_whole.h5", f->scene, f->error_mm);
    csCliResult res;
    cs_cliRun(exe_path, args, "levelscli", &res);
    CS_EXPECT(res.status == 0 && strstr(res.err, "within --tol passed over") != NULL);
    expectRuns(f->scene, f->error_mm, k);
    remove("levelscli_whole.h5");
    remove("levelscli_whole.xdmf");
  }
  printf("  %d of %d rows judged; %d failing row(s) cheaper than the pick at their own error "
         "(the first run here)\n", judged, g_t.nrow, passed);
  CS_EXPECT(cs_cliWriteText("levelscli_whole.csv",
                            "scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,"
                            "error_mm,whole_run,cpu_s_per_s,wall_s_per_s,machine\n"
                            "flat-road,strain,2,1,0.005,1,2,0,0.5,0,0.2,0.2,m\n"
                            "flat-road,strain,2,1,0.002,1,1,0,2,1,0.3,0.3,m\n"));
  expectError("--legs auto --tol 1 --levels levelscli_whole.csv",
              "with a whole run that reaches the scene's goal: 1 row within it fails its own");
  remove("levelscli_whole.csv");
}


/* the benchmark's full table (docs/levels_bench.csv) has every task and every level in it */
static void test_levels_benchmark_has_every_task_and_level(void) {
  char path[1100];
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(path, sizeof path, "%s/docs/levels_bench.csv", src ? src : ".");
  static char text[1 << 16];
  cs_cliSlurp(path, text, sizeof text);
  CS_EXPECT(text[0] != '\0');
  static const char* const kWant[] = {
      "\nflat-road,rod,", "\nobstacle,rod,",
      "\"(1) bend O12 ", "\"(2) bend O12 + tip load", ",analytic,", ",rod,", ",fe,"};
  for (size_t i = 0; i < sizeof kWant / sizeof kWant[0]; i++) {
    CS_EXPECT(strstr(text, kWant[i]) != NULL);
    if (!strstr(text, kWant[i])) {
      printf("  %s has no '%s'\n", path, kWant[i]);
    }
  }
}


static void test_levels_bad_table_and_options_refused(void) {
  CS_EXPECT(cs_cliWriteText("levelscli_table.csv",
                            "scene,level,links,macro_steps,dt_s,error_mm,cpu_s_per_s,"
                            "wall_s_per_s,machine\n"
                            "flat-road,strain,2,1,0.001,50,1.0,2.0,m\n"
                            "flat-road,rod,4,1,0.001,5,-3.0,6.0,m\n"));
  expectError("--legs auto --tol 10 --levels levelscli_table.csv",
              "crawlsim run: levelscli_table.csv:3: cpu_s_per_s -3 is outside");
  expectError("--legs auto --tol 10 --levels levelscli_missing.csv", "levelscli_missing.csv");
  expectError("--legs auto", "--legs auto needs --tol MM");
  expectError("--legs rod --tol 5", "--tol and --levels go with --legs auto");
  expectError("--legs auto --tol 5 --links 4", "--legs auto sets --links");
  expectError("--legs auto --tol nan", "--tol 'nan' is not a finite number");
  remove("levelscli_table.csv");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_levels_cli <path of crawlsim> [case filter]\n");
    return 1;
  }
  exe_path = argv[1];
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_table, sizeof g_table, "%s/robot/levels.csv", src ? src : ".");
  cs_testInit(argc - 1, argv + 1);
  CS_RUN(test_levels_shipped_table_loose_cheaper_than_tight_on_both_scenes);
  CS_RUN(test_levels_strain_step_picks_its_kind);
  CS_RUN(test_levels_failing_whole_run_never_picked);
  CS_RUN(test_levels_benchmark_has_every_task_and_level);
  CS_RUN(test_levels_bad_table_and_options_refused);
  return cs_testSummary();
}
