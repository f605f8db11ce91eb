/* test_levels.c: the leg-level table of `--legs auto` (robot_levels.h): a good table reads;
 * every bad line is refused with one message naming the file, the line and the cause; the pick
 * takes the cheapest row within the tolerance (a loose tolerance a cheaper row than a tight
 * one), and a tolerance no row meets names the best achievable error. Synthetic tables: the
 * numbers are test inputs, not measurements. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "robot_levels.h"

/* format 1 (no rod_tol column: every row at 1), format 2, format 3 (step_order), format 4
 * (step_tol_mm) and format 5 (whole_run) */
#define HEADER "scene,level,links,macro_steps,dt_s,error_mm,cpu_s_per_s,wall_s_per_s,machine\n"
#define HEADER2 \
  "scene,level,links,macro_steps,dt_s,rod_tol,error_mm,cpu_s_per_s,wall_s_per_s,machine\n"
#define HEADER3                                                                             \
  "scene,level,links,macro_steps,dt_s,rod_tol,step_order,error_mm,cpu_s_per_s,wall_s_per_s," \
  "machine\n"
#define HEADER4                                                                             \
  "scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,error_mm,cpu_s_per_s,"   \
  "wall_s_per_s,machine\n"
#define HEADER5                                                                             \
  "scene,level,links,macro_steps,dt_s,rod_tol,step_order,step_tol_mm,error_mm,whole_run,"     \
  "cpu_s_per_s,wall_s_per_s,machine\n"
#define PATH "test_levels.csv"

static csrLevelTable g_t; /* large: not on the stack */


/* write text to PATH and read it; returns the status, err filled */
static csStatus readText(const char* text, csError* err) {
  FILE* f = fopen(PATH, "wb");
  if (!f) {
    return CS_ERR_IO;
  }
  fputs(text, f);
  fclose(f);
  cs_errorClear(err);
  return csr_levelTableRead(PATH, &g_t, err);
}


/* the table is refused with a message that starts "<PATH>:<line>:" and contains `cause` */
static void expectRefused(const char* text, int line, const char* cause) {
  csError err;
  csStatus st = readText(text, &err);
  char where[64];
  snprintf(where, sizeof where, PATH ":%d: ", line);
  CS_EXPECT(st != CS_OK);
  CS_EXPECT(g_t.nrow == 0);
  CS_EXPECT(strstr(err.msg, where) == err.msg);
  CS_EXPECT(strstr(err.msg, cause) != NULL);
  CS_EXPECT(strchr(err.msg, '\n') == NULL);
  if (st == CS_OK || strstr(err.msg, where) != err.msg || !strstr(err.msg, cause)) {
    printf("  got: %s (wanted line %d, '%s')\n", err.msg, line, cause);
  }
}


static const char kGood[] =
    "# comment\n"
    "\n" HEADER
    "flat-road,strain,2,1,0.001,50,1.0,2.0,test machine\n"
    "flat-road,rod,4,1,0.001,5,3.0,6.0,test machine\r\n"
    "flat-road,rod,6,1,0.001,1,5.0,9.0,test machine\n"
    "obstacle,rod,2,2,0.001,30,0.5,1.0,test machine\n"
    "obstacle,strain,4,1,0.001,8,2.5,5.0,test machine\n";


static void test_levels_good_table_reads(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK);
  CS_EXPECT(g_t.nrow == 5);
  CS_EXPECT(!strcmp(g_t.row[1].level, "rod") && g_t.row[1].links == 4 && g_t.row[1].line == 5);
  CS_EXPECT(!strcmp(g_t.row[1].machine, "test machine")); /* the CR of CRLF is not kept */
  CS_EXPECT(g_t.row[3].macro_steps == 2 && g_t.row[3].dt_s == 0.001);
  CS_EXPECT(csr_levelTableCount(&g_t, "flat-road") == 3);
  CS_EXPECT(csr_levelTableCount(&g_t, "obstacle") == 2);
  CS_EXPECT(csr_levelTableFinest(&g_t, "flat-road") == 2);
  CS_EXPECT(csr_levelTableCostliest(&g_t, "flat-road") == 2);
  CS_EXPECT(csr_levelTableCostliest(&g_t, "obstacle") == 4);
  CS_EXPECT(csr_levelTableCostliest(&g_t, "moon") == -1);
}


static void test_levels_loose_tolerance_picks_cheaper_than_tight(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK);
  const char* scenes[2] = {"flat-road", "obstacle"};
  for (int s = 0; s < 2; s++) {
    int loose = csr_levelTablePick(&g_t, scenes[s], 100, &err);
    int tight = csr_levelTablePick(&g_t, scenes[s], 8, &err);
    CS_EXPECT(loose >= 0 && tight >= 0);
    if (loose >= 0 && tight >= 0) {
      CS_EXPECT(g_t.row[loose].cpu_s_per_s < g_t.row[tight].cpu_s_per_s);
      CS_EXPECT(g_t.row[tight].error_mm <= 8 && g_t.row[loose].error_mm <= 100);
    }
  }
  /* the cheapest within: 5 mm takes rod 4 (3 CPU s/s), not rod 6 (5), not strain (50 mm) */
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 5, &err) == 1);
  /* a tolerance on a row's error admits it (<=) */
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 1, &err) == 2);
}


static void test_levels_unmet_tolerance_names_best_error(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK);
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 0.5, &err) == -1);
  CS_EXPECT(strstr(err.msg, "no level meets --tol 0.5 mm on flat-road") != NULL);
  CS_EXPECT(strstr(err.msg, "best achievable is 1 mm (rod, links 6") != NULL);
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePick(&g_t, "stairs", 100, &err) == -1);
  CS_EXPECT(strstr(err.msg, "no row for scene 'stairs'") != NULL);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", NAN, &err) == -1);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", -1, &err) == -1);
}


static void test_levels_bad_lines_refused(void) {
  expectRefused("scene,level,links\n", 1, "the header must be");
  expectRefused("# only a comment\n", 1, "no header line");
  expectRefused(HEADER, 1, "no rows after the header");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,50,1.0,2.0\n", 2, "8 fields, expected 9");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,50,1.0,2.0,m,extra\n", 2, "10 fields");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,50,1.0,2.0,m\n"
                "obstacle,strain,2,1,0.001,fifty,1.0,2.0,m\n", 3, "error_mm 'fifty' is not a number");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,nan,1.0,2.0,m\n", 2, "error_mm 'nan' is not a "
                "finite number");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,1e999,1.0,2.0,m\n", 2, "not a finite number");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,-1,1.0,2.0,m\n", 2, "error_mm -1 is outside");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,5,0,2.0,m\n", 2, "cpu_s_per_s 0 is outside");
  expectRefused(HEADER "flat-road,strain,0,1,0.001,5,1,2.0,m\n", 2, "links 0 is outside");
  expectRefused(HEADER "flat-road,strain,2.5,1,0.001,5,1,2.0,m\n", 2, "links 2.5 is not an integer");
  expectRefused(HEADER "flat-road,strain,2,1,0.02,5,1,2.0,m\n", 2, "dt_s 0.02 is outside");
  expectRefused(HEADER "flat-road,strain,2,1,,5,1,2.0,m\n", 2, "dt_s '' is not a number");
  expectRefused(HEADER "flat-road,fem,2,1,0.001,5,1,2.0,m\n", 2, "level 'fem' is not a leg level");
  expectRefused(HEADER "flat-road,rom,2,1,0.001,5,1,2.0,m\n", 2, "level 'rom' runs from a leg file of its own (--rom-file)");
  /* a retired level: one line naming why and what to use */
  expectRefused(HEADER "flat-road,prb,2,1,0.001,5,1,2.0,m\n", 2, "level 'prb' is the prb level "
                "was retired");
  expectRefused(HEADER "flat-road,prb,2,1,0.001,5,1,2.0,m\n", 2, "use rod (the default) or "
                "strain");
  expectRefused(HEADER ",strain,2,1,0.001,5,1,2.0,m\n", 2, "scene '' must be one word");
  expectRefused(HEADER "flat road,strain,2,1,0.001,5,1,2.0,m\n", 2, "must be one word");
  expectRefused(HEADER "flat-road,strain,2,1,0.001,5,1,2.0,m\n"
                "flat-road,strain,2,1,0.001,6,2,3.0,m\n", 3, "repeats the configuration of line 2");
  /* an empty file: one line naming it, no line 0 (found by fuzz_levels) */
  csError e0;
  CS_EXPECT(readText("", &e0) == CS_ERR_PARSE);
  CS_EXPECT(strstr(e0.msg, PATH ": empty file") == e0.msg && !strstr(e0.msg, ":0:"));
  /* a missing file: one line naming it */
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTableRead("no_such_levels.csv", &g_t, &err) == CS_ERR_IO);
  CS_EXPECT(strstr(err.msg, "no_such_levels.csv") != NULL && !strchr(err.msg, '\n'));
}


/* format 2: the rod_tol column is read and range-checked, is part of a configuration (two
 * rows differing only in it are two configurations), and format 1 rows read as rod_tol 1 */
static void test_levels_format2_rod_tol(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK && g_t.nrow == 5 && g_t.row[0].rod_tol == 1);
  static const char kGood2[] =
      HEADER2
      "flat-road,rod,4,1,0.001,1,5,3.0,6.0,m\n"
      "flat-road,rod,4,1,0.001,10,8,1.0,2.0,m\n"
      "flat-road,strain,4,1,0.001,1,30,4.0,4.0,m\n";
  CS_EXPECT(readText(kGood2, &err) == CS_OK);
  CS_EXPECT(g_t.nrow == 3 && g_t.row[1].rod_tol == 10 && g_t.row[1].error_mm == 8 &&
            g_t.row[1].cpu_s_per_s == 1.0 && !strcmp(g_t.row[1].machine, "m"));
  /* the looser row is the cheaper one within 8 mm, the tight one within 5 */
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 8, &err) == 1);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 5, &err) == 0);
  expectRefused(HEADER2 "flat-road,rod,4,1,0.001,0,5,3.0,6.0,m\n", 2, "rod_tol 0 is outside (0");
  expectRefused(HEADER2 "flat-road,rod,4,1,0.001,2000,5,3.0,6.0,m\n", 2, "rod_tol 2000 is");
  expectRefused(HEADER2 "flat-road,rod,4,1,0.001,x,5,3.0,6.0,m\n", 2, "rod_tol 'x' is not a");
  expectRefused(HEADER2 "flat-road,rod,4,1,0.001,5,3.0,6.0,m\n", 2, "9 fields, expected 10");
  expectRefused(HEADER2 "flat-road,rod,4,1,0.001,2,5,3.0,6.0,m\n"
                        "flat-road,rod,4,1,0.001,2,6,3.0,6.0,m\n", 3, "rod tol 2");
}


/* format 3: the step_order column is read (0..2, an integer), is part of a configuration (a
 * strain row at 5 ms in BE and in BDF2 are two), and format 1 and 2 rows read as step order 0
 * (the level's default formula) */
static void test_levels_format3_step_order(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK && g_t.row[0].step_order == 0);
  static const char kGood3[] =
      HEADER3
      "flat-road,strain,3,1,0.005,1,2,4,0.5,0.6,m\n"
      "flat-road,strain,3,1,0.005,1,1,9,0.4,0.5,m\n"
      "flat-road,rod,8,1,0.001,1,0,3,1.5,1.6,m\n";
  CS_EXPECT(readText(kGood3, &err) == CS_OK);
  CS_EXPECT(g_t.nrow == 3 && g_t.row[0].step_order == 2 && g_t.row[1].step_order == 1 &&
            g_t.row[0].error_mm == 4 && g_t.row[0].cpu_s_per_s == 0.5 &&
            g_t.row[2].rod_tol == 1 && !strcmp(g_t.row[2].machine, "m"));
  /* within 5 mm the BDF2 row, within 9 the cheaper BE one */
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 5, &err) == 0);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 9, &err) == 1);
  expectRefused(HEADER3 "flat-road,strain,3,1,0.005,1,3,4,0.5,0.6,m\n", 2,
                "step_order 3 is outside [0, 2]");
  expectRefused(HEADER3 "flat-road,strain,3,1,0.005,1,1.5,4,0.5,0.6,m\n", 2,
                "step_order 1.5 is not an integer");
  expectRefused(HEADER3 "flat-road,strain,3,1,0.005,1,4,0.5,0.6,m\n", 2, "10 fields, expected 11");
  expectRefused(HEADER3 "flat-road,strain,3,1,0.005,1,2,4,0.5,0.6,m\n"
                        "flat-road,strain,3,1,0.005,1,2,5,0.5,0.6,m\n", 3, "step order 2");
}


/* format 4: the step_tol_mm column (0 a fixed step, > 0 the adaptive step at that tolerance, dt
 * its longest) is read, range-checked, part of a configuration (the fixed 5 ms and the adaptive
 * step up to 5 ms are two), allowed only where the run would take it (a tree-stepped level,
 * backward Euler), and the pick can be held to one kind (--strain-step beside --legs auto);
 * format 3 rows read as fixed steps */
static void test_levels_format4_step_tol(void) {
  csError err;
  static const char kGood3[] = HEADER3 "flat-road,strain,2,1,0.005,1,1,4,0.5,0.6,m\n";
  CS_EXPECT(readText(kGood3, &err) == CS_OK && g_t.row[0].step_tol_mm == 0);
  CS_EXPECT(readText(kGood, &err) == CS_OK && g_t.row[0].step_tol_mm == 0);
  static const char kGood4[] =
      HEADER4
      "flat-road,strain,2,1,0.005,1,1,0,4,0.25,0.3,m\n"
      "flat-road,strain,2,1,0.005,1,1,0.00025,2,0.9,1.0,m\n"
      "flat-road,strain,2,1,0.005,1,0,0.0005,3,0.6,0.7,m\n"
      "flat-road,rod,8,1,0.001,1,0,0,3.5,2.0,2.1,m\n";
  CS_EXPECT(readText(kGood4, &err) == CS_OK);
  CS_EXPECT(g_t.nrow == 4 && g_t.row[0].step_tol_mm == 0 && g_t.row[1].step_tol_mm == 0.00025 &&
            g_t.row[2].step_tol_mm == 0.0005 && g_t.row[1].error_mm == 2 &&
            g_t.row[1].cpu_s_per_s == 0.9 && g_t.row[1].wall_s_per_s == 1.0 &&
            !strcmp(g_t.row[3].machine, "m"));
  /* any kind: within 4 mm the fixed 5 ms (the cheapest), within 3 the looser adaptive row,
   * within 2 the tighter one */
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 4, &err) == 0);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 3, &err) == 2);
  CS_EXPECT(csr_levelTablePick(&g_t, "flat-road", 2, &err) == 1);
  /* one kind: within 4 mm the adaptive rows only take the cheaper adaptive one; fixed steps
   * within 3.5 the rod */
  CS_EXPECT(csr_levelTablePickStep(&g_t, "flat-road", 4, CSR_STEP_ADAPTIVE, &err) == 2);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "flat-road", 3.5, CSR_STEP_FIXED, &err) == 3);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "flat-road", 3.5, CSR_STEP_ANY, &err) == 2);
  /* none of the kind within: the best of that kind is named */
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "flat-road", 1, CSR_STEP_ADAPTIVE, &err) == -1);
  CS_EXPECT(strstr(err.msg, "with the adaptive step") != NULL &&
            strstr(err.msg, "best achievable is 2 mm") != NULL &&
            strstr(err.msg, "adaptive step at 0.00025 mm, line 3") != NULL);
  if (!strstr(err.msg, "adaptive step at 0.00025 mm, line 3")) {
    printf("  got: %s\n", err.msg);
  }
  /* a scene without rows of the kind: said so */
  static const char kFixed[] = HEADER4 "obstacle,strain,2,1,0.005,1,1,0,4,0.25,0.3,m\n";
  CS_EXPECT(readText(kFixed, &err) == CS_OK);
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "obstacle", 100, CSR_STEP_ADAPTIVE, &err) == -1);
  CS_EXPECT(err.status == CS_ERR_ARG && strstr(err.msg, "no row for scene 'obstacle' with the "
                                               "adaptive step") != NULL);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "obstacle", 100, CSR_STEP_FIXED, &err) == 0);
  /* bad values and rows the run would refuse: one line each */
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,-1e-4,4,0.25,0.3,m\n", 2,
                "step_tol_mm -0.0001 is outside [0, 100]");
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,101,4,0.25,0.3,m\n", 2,
                "step_tol_mm 101 is outside");
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,nan,4,0.25,0.3,m\n", 2,
                "step_tol_mm 'nan' is not a finite number");
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,tight,4,0.25,0.3,m\n", 2,
                "step_tol_mm 'tight' is not a number");
  expectRefused(HEADER4 "flat-road,rod,8,1,0.001,1,0,2.5e-4,3,2,2,m\n", 2,
                "step_tol_mm 0.00025 on level 'rod': the adaptive step is a tree-stepped");
  /* the adaptive step estimates either formula's error (core/sim_adaptive.c): a BDF2 row reads */
  CS_EXPECT(readText(HEADER4 "flat-road,strain,2,1,0.005,1,2,2.5e-4,3,2,2,m\n", &err) == CS_OK);
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,2.5e-4,4,0.25,0.3,m\n"
                        "flat-road,strain,2,1,0.005,1,1,0.00025,5,0.3,0.4,m\n", 3,
                "step tol 0.00025 mm");
  /* a format 4 header on format 3 rows: counted, not shifted */
  expectRefused(HEADER4 "flat-road,strain,2,1,0.005,1,1,4,0.25,0.3,m\n", 2,
                "11 fields, expected 12");
}


/* format 5: the whole_run column (1 the scene's whole run reaches its goal, 0 it does not, -1
 * not judged) is read and range-checked; older formats read as -1; a row whose whole run fails
 * is never picked however cheap and accurate on its window (the obstacle's first 4 s within
 * 1 mm, then off the step at 12 s), the pick's note can count what it passed over, and a
 * tolerance met only by failing rows names them */
static void test_levels_format5_failing_whole_run_never_picked(void) {
  csError err;
  CS_EXPECT(readText(kGood, &err) == CS_OK && g_t.row[0].whole_run == -1);
  static const char kGood4[] = HEADER4 "flat-road,strain,2,1,0.005,1,1,0,4,0.25,0.3,m\n";
  CS_EXPECT(readText(kGood4, &err) == CS_OK && g_t.row[0].whole_run == -1);
  static const char kGood5[] =
      HEADER5
      "obstacle,strain,2,1,0.005,1,2,0,0.8,0,0.27,0.3,m\n"
      "obstacle,strain,2,1,0.005,1,1,0.00025,0.24,1,0.41,0.42,m\n"
      "obstacle,rod,4,1,0.001,1,0,0,0.67,-1,0.77,0.78,m\n"
      "obstacle,rod,2,1,0.001,1,0,0,1.37,1,0.35,0.5,m\n";
  CS_EXPECT(readText(kGood5, &err) == CS_OK);
  CS_EXPECT(g_t.nrow == 4 && g_t.row[0].whole_run == 0 && g_t.row[1].whole_run == 1 &&
            g_t.row[2].whole_run == -1 && g_t.row[0].error_mm == 0.8 &&
            g_t.row[0].cpu_s_per_s == 0.27 && g_t.row[3].wall_s_per_s == 0.5);
  /* within 1 mm the cheapest row (0.27) fails its whole run: the adaptive row is picked, and
   * one cheaper row was passed over */
  CS_EXPECT(csr_levelTablePick(&g_t, "obstacle", 1, &err) == 1);
  CS_EXPECT(csr_levelTableFailing(&g_t, "obstacle", 1, CSR_STEP_ANY, 0.41) == 1);
  CS_EXPECT(csr_levelTableFailing(&g_t, "obstacle", 0.5, CSR_STEP_ANY, 0.41) == 0);
  /* within 2 mm: the rod at 2 elements (0.35) is cheaper than the adaptive row, the failing
   * row still skipped; a row not judged (-1) may be picked */
  CS_EXPECT(csr_levelTablePick(&g_t, "obstacle", 2, &err) == 3);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "obstacle", 2, CSR_STEP_FIXED, &err) == 3);
  CS_EXPECT(csr_levelTablePickStep(&g_t, "obstacle", 0.7, CSR_STEP_FIXED, &err) == 2);
  /* only failing rows within the tolerance: refused, naming them */
  CS_EXPECT(csr_levelTablePickStep(&g_t, "obstacle", 0.9, CSR_STEP_FIXED, &err) == 2);
  static const char kFail5[] = HEADER5 "obstacle,strain,2,1,0.005,1,2,0,0.8,0,0.27,0.3,m\n"
                                       "obstacle,rod,2,1,0.001,1,0,0,1.37,1,0.35,0.5,m\n";
  CS_EXPECT(readText(kFail5, &err) == CS_OK);
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePick(&g_t, "obstacle", 1, &err) == -1);
  CS_EXPECT(err.status == CS_ERR_RANGE &&
            strstr(err.msg, "with a whole run that reaches the scene's goal") != NULL &&
            strstr(err.msg, "1 row within it fails its own") != NULL &&
            strstr(err.msg, "(whole_run 0; the cheapest strain, links 2") != NULL &&
            strstr(err.msg, "line 2)") != NULL && strchr(err.msg, '\n') == NULL);
  if (!strstr(err.msg, "line 2)")) {
    printf("  got: %s\n", err.msg);
  }
  /* every row of the scene fails: said so (no best achievable among them) */
  CS_EXPECT(readText(HEADER5 "obstacle,strain,2,1,0.005,1,2,0,0.8,0,0.27,0.3,m\n", &err) == CS_OK);
  cs_errorClear(&err);
  CS_EXPECT(csr_levelTablePick(&g_t, "obstacle", 0.5, &err) == -1);
  CS_EXPECT(err.status == CS_ERR_RANGE &&
            strstr(err.msg, "every row for scene 'obstacle' fails the scene's whole run") != NULL);
  /* bad values: one line each */
  expectRefused(HEADER5 "obstacle,rod,2,1,0.001,1,0,0,1.37,2,0.48,0.5,m\n", 2,
                "whole_run 2 is outside [-1, 1]");
  expectRefused(HEADER5 "obstacle,rod,2,1,0.001,1,0,0,1.37,0.5,0.48,0.5,m\n", 2,
                "whole_run 0.5 is not an integer");
  expectRefused(HEADER5 "obstacle,rod,2,1,0.001,1,0,0,1.37,yes,0.48,0.5,m\n", 2,
                "whole_run 'yes' is not a number");
  /* a format 5 header on format 4 rows: counted, not shifted */
  expectRefused(HEADER5 "obstacle,rod,2,1,0.001,1,0,0,1.37,0.48,0.5,m\n", 2,
                "12 fields, expected 13");
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_levels_good_table_reads);
  CS_RUN(test_levels_loose_tolerance_picks_cheaper_than_tight);
  CS_RUN(test_levels_unmet_tolerance_names_best_error);
  CS_RUN(test_levels_bad_lines_refused);
  CS_RUN(test_levels_format2_rod_tol);
  CS_RUN(test_levels_format3_step_order);
  CS_RUN(test_levels_format4_step_tol);
  CS_RUN(test_levels_format5_failing_whole_run_never_picked);
  remove(PATH);
  return cs_testSummary();
}
