/* test_gaits_csv.c: the gait table (gaits_csv.h): building in code, validation, the CSV
 * reader on good input (CRLF, BOM, comments, subsets, any column order, label numbers), a
 * write -> read round trip of a random table, the `# @ramp` directive, and every bad-input
 * case, each checked for its status AND a one-line message naming the file, line and column. Files are written into the
 * working directory (the build tree). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_csv.h"

/* round-trip tolerance of written pressures: %.6g keeps 6 significant digits, so the
 * relative error is at most 5e-6 (half a unit in the 6th digit, relative to a leading 1) */
#define PRESSURE_REL_TOL 5e-6


/* write `n` bytes of `text` to `path` (binary, so "\r\n" and "\0" stay as given) */
static void writeBytes(const char* path, const char* text, size_t n) {
  FILE* f = fopen(path, "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    CS_EXPECT(fwrite(text, 1, n, f) == n);
    fclose(f);
  }
}


static void writeText(const char* path, const char* text) { writeBytes(path, text, strlen(text)); }


/* read `path` expecting failure with `status`; the message must be one line and contain
 * "<path>:<line>:" (line > 0) and "column <col>" (col > 0) and `cause` (if not NULL) */
static void expectBad(const char* path, const csgReadOptions* opt, csStatus status, int line,
                      int col, const char* cause) {
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitRead(path, opt, &err);
  CS_EXPECT(g == NULL);
  csg_gaitDestroy(g);
  CS_EXPECT(err.status == status);
  CS_EXPECT(strchr(err.msg, '\n') == NULL && strchr(err.msg, '\r') == NULL);
  CS_EXPECT(strstr(err.msg, path) == err.msg);
  char want[256];
  int ok = 1;
  if (line > 0) {
    snprintf(want, sizeof want, "%s:%d:", path, line);
    ok &= strstr(err.msg, want) != NULL;
  }
  if (col > 0) {
    snprintf(want, sizeof want, "column %d", col);
    ok &= strstr(err.msg, want) != NULL;
  }
  if (cause) {
    ok &= strstr(err.msg, cause) != NULL;
  }
  CS_EXPECT(ok);
  if (!ok || err.status != status) {
    fprintf(stderr, "  %s: status %d, message: %s\n", path, (int)err.status, err.msg);
  }
}


/* write `text` to `path` and expect the reader to refuse it (defaults) */
static void bad(const char* path, const char* text, csStatus status, int line, int col,
                const char* cause) {
  writeText(path, text);
  expectBad(path, NULL, status, line, col, cause);
}


/* a small deterministic generator: no global state (xorshift64*), uniform in [0, 1) */
static double uniform(unsigned long long* s) {
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return (double)((*s * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}


/* ---- building and validation ---- */

static void test_buildInCode(void) {
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitCreate(2, &err);
  CS_EXPECT(g != NULL && g->nrow == 2);
  if (!g) {
    return;
  }
  CS_EXPECT(csg_gaitTime(g, 1) == 0.0 && csg_gaitPressure(g, 1, 96) == 0.0);
  CS_EXPECT(csg_gaitSetTime(g, 0, 0.0, &err) == CS_OK);
  CS_EXPECT(csg_gaitSetTime(g, 1, 1.0, &err) == CS_OK);
  CS_EXPECT(csg_gaitSetPressure(g, 0, 22, 0.18, &err) == CS_OK);
  CS_EXPECT(csg_gaitPressure(g, 0, 22) == 0.18);
  CS_EXPECT(g->pressure[22 - 1] == 0.18); /* row-major (nrow x 96), column label-1 */
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_OK);

  /* growing keeps old rows and zeroes new ones; shrinking keeps the first rows */
  CS_EXPECT(csg_gaitSetRowCount(g, 40, &err) == CS_OK && g->nrow == 40);
  CS_EXPECT(csg_gaitPressure(g, 0, 22) == 0.18 && csg_gaitTime(g, 1) == 1.0);
  CS_EXPECT(csg_gaitTime(g, 39) == 0.0 && csg_gaitPressure(g, 39, 1) == 0.0);
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE); /* rows 2.. have time 0 */
  CS_EXPECT(strstr(err.msg, "row 2") != NULL);
  CS_EXPECT(csg_gaitSetRowCount(g, 2, &err) == CS_OK && g->nrow == 2);
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_OK);

  /* argument errors leave the table as it was */
  CS_EXPECT(csg_gaitSetTime(g, 2, 3.0, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetTime(g, -1, 3.0, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetTime(g, 0, NAN, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetPressure(g, 0, 0, 0.1, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetPressure(g, 0, 97, 0.1, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetPressure(g, 0, 1, INFINITY, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitSetRowCount(g, -1, &err) == CS_ERR_ARG && g->nrow == 2);
  CS_EXPECT(csg_gaitTime(g, 0) == 0.0 && csg_gaitPressure(g, 0, 1) == 0.0);
  CS_EXPECT(isnan(csg_gaitTime(g, 2)) && isnan(csg_gaitPressure(g, 0, 97)));
  CS_EXPECT(isnan(csg_gaitTime(NULL, 0)));
  csg_gaitDestroy(g);
  csg_gaitDestroy(NULL); /* NULL-safe */
  CS_EXPECT(csg_gaitCreate(-1, &err) == NULL && err.status == CS_ERR_ARG);

  /* an empty table is allowed while building, invalid as a gait */
  g = csg_gaitCreate(0, &err);
  CS_EXPECT(g != NULL);
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_ARG);
  csg_gaitDestroy(g);
}


static void test_validateRules(void) {
  csError err;
  csgGait* g = csg_gaitCreate(3, &err);
  if (!g) {
    CS_EXPECT(0);
    return;
  }
  csg_gaitSetTime(g, 0, 0.5, &err);
  csg_gaitSetTime(g, 1, 1.0, &err);
  csg_gaitSetTime(g, 2, 2.0, &err);
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_OK);

  csg_gaitSetTime(g, 0, -0.5, &err); /* negative time */
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE && strstr(err.msg, "row 0"));
  csg_gaitSetTime(g, 0, 1.0, &err); /* equal to the next: not strictly increasing */
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE && strstr(err.msg, "row 1"));
  csg_gaitSetTime(g, 0, 0.5, &err);

  csg_gaitSetPressure(g, 2, 5, -0.01, &err); /* negative pressure, named by chamber */
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE && strstr(err.msg, "row 2") &&
            strstr(err.msg, "A_II2_O1"));
  csg_gaitSetPressure(g, 2, 5, 1.5, &err); /* above the default 1 MPa */
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE && strstr(err.msg, "limit"));
  csgReadOptions opt = csg_defaultReadOptions();
  opt.max_pressure = 2.0;
  CS_EXPECT(csg_gaitValidate(g, &opt, &err) == CS_OK);
  opt.max_rows = 2;
  CS_EXPECT(csg_gaitValidate(g, &opt, &err) == CS_ERR_RANGE);
  opt.max_rows = 0; /* bad options */
  CS_EXPECT(csg_gaitValidate(g, &opt, &err) == CS_ERR_ARG);
  CS_EXPECT(csg_gaitValidate(NULL, NULL, &err) == CS_ERR_ARG);
  csg_gaitDestroy(g);
}


static void test_defaults(void) {
  csgReadOptions o = csg_defaultReadOptions();
  CS_EXPECT(o.max_pressure == 1.0);
  CS_EXPECT(o.max_rows == 100000L);
  CS_EXPECT(o.max_line_bytes == 65536);
}


/* ---- reading good input ---- */

static void test_readGood(void) {
  /* CRLF, BOM, comments and blank lines anywhere, spaces and tabs around fields, names and
   * label numbers, any order, a subset, last line without a newline */
  const char text[] =
      "\xEF\xBB\xBF# flat-road excerpt\r\n"
      "\r\n"
      "  # indented comment\r\n"
      "time, B_II3_O2 ,3,\tH_II3_O4\r\n"
      "0, 0.18, 0 ,0.25  \r\n"
      "# between rows\r\n"
      "\r\n"
      "1.5,0,1e-1,\t0.3\t\r\n"
      "2,0,0,0";
  writeText("good_crlf.csv", text);
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitRead("good_crlf.csv", NULL, &err);
  CS_EXPECT(g != NULL);
  if (!g) {
    fprintf(stderr, "  %s\n", err.msg);
    return;
  }
  CS_EXPECT(g->nrow == 3);
  CS_EXPECT(g->time[0] == 0.0 && g->time[1] == 1.5 && g->time[2] == 2.0);
  CS_EXPECT(csg_gaitPressure(g, 0, 22) == 0.18);
  CS_EXPECT(csg_gaitPressure(g, 0, 96) == 0.25);
  CS_EXPECT(csg_gaitPressure(g, 1, 3) == 0.1);
  CS_EXPECT(csg_gaitPressure(g, 1, 96) == 0.3);
  /* chambers not named are 0 in every row */
  int others_zero = 1;
  for (int i = 0; i < g->nrow; i++) {
    for (int l = 1; l <= CSG_NLABEL; l++) {
      if (l != 22 && l != 3 && l != 96) {
        others_zero &= csg_gaitPressure(g, i, l) == 0.0;
      }
    }
  }
  CS_EXPECT(others_zero);

  csgGaitSummary s;
  CS_EXPECT(csg_gaitComputeSummary(g, &s, &err) == CS_OK);
  CS_EXPECT(s.nrow == 3 && s.t_first == 0.0 && s.t_last == 2.0);
  CS_EXPECT(s.nused == 3);
  CS_EXPECT(s.p_max == 0.3 && s.p_max_label == 96 && s.p_max_row == 1);
  csg_gaitDestroy(g);

  /* a header with only `time`: every chamber vented; trailing spaces after numbers */
  writeText("good_time_only.csv", "time\n0\n1   \n");
  g = csg_gaitRead("good_time_only.csv", NULL, &err);
  CS_EXPECT(g != NULL && g->nrow == 2);
  if (g) {
    CS_EXPECT(csg_gaitComputeSummary(g, &s, &err) == CS_OK && s.nused == 0 && s.p_max == 0.0 &&
              s.p_max_label == 0 && s.p_max_row == -1);
  }
  csg_gaitDestroy(g);

  /* a raised limit admits what the default refuses */
  writeText("good_high.csv", "time,1\n0,1.5\n");
  csgReadOptions opt = csg_defaultReadOptions();
  opt.max_pressure = 2.0;
  g = csg_gaitRead("good_high.csv", &opt, &err);
  CS_EXPECT(g != NULL && csg_gaitPressure(g, 0, 1) == 1.5);
  csg_gaitDestroy(g);
}


/* ---- round trip ---- */

static void test_roundTripRandom(void) {
  enum { NROW = 37 };
  unsigned long long seed = 0x9E3779B97F4A7C15ULL;
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitCreate(NROW, &err);
  if (!g) {
    CS_EXPECT(0);
    return;
  }
  double t = 0.0;
  for (int i = 0; i < NROW; i++) {
    /* irregular spacing, including values with no short decimal form */
    t += 1e-3 + uniform(&seed);
    CS_EXPECT(csg_gaitSetTime(g, i, i == 0 ? 0.0 : t, &err) == CS_OK);
    for (int l = 1; l <= CSG_NLABEL; l++) {
      double u = uniform(&seed);
      double p = u < 0.5 ? 0.0 : 0.9 * uniform(&seed); /* about half the chambers vented */
      CS_EXPECT(csg_gaitSetPressure(g, i, l, p, &err) == CS_OK);
    }
  }
  const char* path = "roundtrip.csv";
  CS_EXPECT(csg_gaitWrite(g, path, "random table\nsecond comment line", &err) == CS_OK);
  csgGait* h = csg_gaitRead(path, NULL, &err);
  CS_EXPECT(h != NULL);
  if (h) {
    CS_EXPECT(h->nrow == NROW);
    int times_exact = 1, worst_ok = 1;
    for (int i = 0; i < NROW && i < h->nrow; i++) {
      times_exact &= h->time[i] == g->time[i]; /* times are written to read back exactly */
      for (int l = 1; l <= CSG_NLABEL; l++) {
        double a = csg_gaitPressure(h, i, l), b = csg_gaitPressure(g, i, l);
        worst_ok &= fabs(a - b) <= PRESSURE_REL_TOL * fabs(b);
      }
    }
    CS_EXPECT(times_exact);
    CS_EXPECT(worst_ok);
  }
  csg_gaitDestroy(h);

  /* the file: two comment lines, then a header of all 96 names in label order */
  FILE* f = fopen(path, "rb");
  char line[4096];
  CS_EXPECT(f && fgets(line, sizeof line, f) && !strcmp(line, "# random table\n"));
  CS_EXPECT(f && fgets(line, sizeof line, f) && !strcmp(line, "# second comment line\n"));
  CS_EXPECT(f && fgets(line, sizeof line, f) && !strncmp(line, "time,A_II1_O1,A_II1_O2,", 23));
  CS_EXPECT(strstr(line, ",H_II3_O4\n") != NULL);
  int ncomma = 0;
  for (const char* c = line; *c; c++) {
    ncomma += *c == ',';
  }
  CS_EXPECT(ncomma == CSG_NLABEL);
  if (f) {
    fclose(f);
  }

  /* the writer refuses an invalid table and writes nothing */
  remove("invalid_written.csv");
  csg_gaitSetTime(g, 3, g->time[2], &err);
  CS_EXPECT(csg_gaitWrite(g, "invalid_written.csv", NULL, &err) == CS_ERR_RANGE);
  f = fopen("invalid_written.csv", "rb");
  CS_EXPECT(f == NULL);
  if (f) {
    fclose(f);
  }
  CS_EXPECT(csg_gaitWrite(g, "no_such_dir/x.csv", NULL, &err) == CS_ERR_RANGE);
  csg_gaitSetTime(g, 3, 0.5 * (g->time[2] + g->time[4]), &err);
  CS_EXPECT(csg_gaitWrite(g, "no_such_dir/x.csv", NULL, &err) == CS_ERR_IO);
  CS_EXPECT(strstr(err.msg, "no_such_dir/x.csv") != NULL);
  csg_gaitDestroy(g);
}


/* ---- bad input: file level ---- */

static void test_badFile(void) {
  remove("does_not_exist.csv");
  expectBad("does_not_exist.csv", NULL, CS_ERR_IO, 0, 0, "cannot open");
  bad("bad_empty.csv", "", CS_ERR_PARSE, 1, 0, "empty file");
  bad("bad_only_comments.csv", "# a\n\n# b\n", CS_ERR_PARSE, 0, 0, "no header");
  bad("bad_no_rows.csv", "# a\ntime,A_II1_O1\n# no data\n\n", CS_ERR_PARSE, 2, 0, "no data rows");
  /* a directory opens but does not read */
  expectBad(".", NULL, CS_ERR_IO, 0, 0, "read error");
  csError err;
  CS_EXPECT(csg_gaitRead(NULL, NULL, &err) == NULL && err.status == CS_ERR_ARG);
  csgReadOptions o = csg_defaultReadOptions();
  o.max_pressure = -1.0;
  CS_EXPECT(csg_gaitRead("bad_empty.csv", &o, &err) == NULL && err.status == CS_ERR_ARG);
}


/* ---- bad input: header ---- */

static void test_badHeader(void) {
  bad("bad_header_t.csv", "t,A_II1_O1\n0,0\n", CS_ERR_PARSE, 1, 1, "'time'");
  bad("bad_header_after_comments.csv", "# x\n# y\nTime,A_II1_O1\n0,0\n", CS_ERR_PARSE, 3, 1,
      "'time'");
  bad("bad_header_semicolon.csv", "time;A_II1_O1\n0;0\n", CS_ERR_PARSE, 1, 1, "';'");
  bad("bad_header_unknown.csv", "time,A_II1_O1,Z_II1_O1\n0,0,0\n", CS_ERR_PARSE, 1, 3, "Z_II1_O1");
  bad("bad_header_label97.csv", "time,97\n0,0\n", CS_ERR_PARSE, 1, 2, "unknown column");
  bad("bad_header_empty_name.csv", "time,A_II1_O1,\n0,0,0\n", CS_ERR_PARSE, 1, 3, "empty");
  /* the same chamber by number and by name */
  bad("bad_header_dup.csv", "time,22,A_II1_O1,B_II3_O2\n0,0,0,0\n", CS_ERR_PARSE, 1, 4, "column 2");
  bad("bad_header_dup_name.csv", "time,H_II3_O4,H_II3_O4\n0,0,0\n", CS_ERR_PARSE, 1, 3, "twice");
}


/* ---- bad input: data rows ---- */

static void test_badRows(void) {
  const char* h = "time,A_II1_O1,A_II1_O2\n"; /* line 1 */
  char text[512];
#define ROWS(rows) (snprintf(text, sizeof text, "%s%s", h, rows), text)
  bad("bad_few_fields.csv", ROWS("0,0.1,0.1\n1,0.1\n"), CS_ERR_PARSE, 3, 3, "missing field");
  bad("bad_many_fields.csv", ROWS("0,0.1,0.1,0.1\n"), CS_ERR_PARSE, 2, 4, "extra field");
  bad("bad_trailing_comma.csv", ROWS("0,0.1,0.1,\n"), CS_ERR_PARSE, 2, 4, "extra field");
  bad("bad_nan_word.csv", ROWS("0,abc,0\n"), CS_ERR_PARSE, 2, 2, "not a number");
  bad("bad_num_suffix.csv", ROWS("0,0.1x,0\n"), CS_ERR_PARSE, 2, 2, "'0.1x'");
  bad("bad_two_dots.csv", ROWS("0,0,1..2\n"), CS_ERR_PARSE, 2, 3, "not a number");
  bad("bad_inner_space.csv", ROWS("0,0,0. 1\n"), CS_ERR_PARSE, 2, 3, "not a number");
  bad("bad_empty_field.csv", ROWS("0,,0\n"), CS_ERR_PARSE, 2, 2, "empty field");
  bad("bad_time_text.csv", ROWS("# c\nzero,0,0\n"), CS_ERR_PARSE, 3, 1, "not a number");
  bad("bad_nan.csv", ROWS("0,nan,0\n"), CS_ERR_RANGE, 2, 2, "not finite");
  bad("bad_inf.csv", ROWS("0,0,-inf\n"), CS_ERR_RANGE, 2, 3, "not finite");
  bad("bad_overflow.csv", ROWS("0,0,1e999\n"), CS_ERR_RANGE, 2, 3, "not finite");
  bad("bad_time_inf.csv", ROWS("Infinity,0,0\n"), CS_ERR_RANGE, 2, 1, "not finite");
  bad("bad_time_equal.csv", ROWS("0,0,0\n1,0,0\n1,0,0\n"), CS_ERR_RANGE, 4, 1, "increase");
  bad("bad_time_back.csv", ROWS("0,0,0\n2,0,0\n# c\n1.5,0,0\n"), CS_ERR_RANGE, 5, 1, "line 3");
  bad("bad_time_negative.csv", ROWS("-1,0,0\n"), CS_ERR_RANGE, 2, 1, "negative time");
  bad("bad_p_negative.csv", ROWS("0,0,0\n1,0,-0.05\n"), CS_ERR_RANGE, 3, 3, "negative pressure");
  bad("bad_p_high.csv", ROWS("0,0,0\n1,1.8,0\n"), CS_ERR_RANGE, 3, 2, "above the limit");
  bad("bad_p_kpa.csv", ROWS("0,180,0\n"), CS_ERR_RANGE, 2, 2, "A_II1_O1");
  bad("bad_mac_cr.csv", "time,A_II1_O1\r0,0\r1,0\r", CS_ERR_PARSE, 1, 0, "carriage return");
#undef ROWS
  /* the column's chamber name is in the message, whatever the header called it */
  bad("bad_named.csv", "time,96\n0,-1\n", CS_ERR_RANGE, 2, 2, "H_II3_O4");

  /* a NUL byte (binary or UTF-16 file) */
  static const char kNul[] = "time,A_II1_O1\n0,0\0\n";
  writeBytes("bad_nul.csv", kNul, sizeof kNul - 1);
  expectBad("bad_nul.csv", NULL, CS_ERR_PARSE, 2, 0, "NUL");
}


/* ---- the `# @ramp S` directive ---- */

/* read where it stands (before the header, among the rows), none = NAN, written back exactly;
 * every bad directive refused with file and line */
static void test_rampDirective(void) {
  csError err;
  writeText("ramp_none.csv", "# a @ramp in prose is a comment\ntime,A_II1_O1\n0,0.1\n");
  csgGait* g = csg_gaitRead("ramp_none.csv", NULL, &err);
  CS_EXPECT(g && isnan(g->ramp));
  csg_gaitDestroy(g);
  writeText("ramp_head.csv", "# designed\n  #  @ramp 0.05  \ntime,A_II1_O1\n0,0.1\n1,0\n");
  g = csg_gaitRead("ramp_head.csv", NULL, &err);
  CS_EXPECT(g && g->ramp == 0.05 && g->nrow == 2);
  if (g) {
    /* written back: the directive reads back to the same double */
    g->ramp = 0.1 + 0.2; /* 0.30000000000000004 needs 17 digits */
    CS_EXPECT(csg_gaitWrite(g, "ramp_written.csv", "comment", &err) == CS_OK);
    csgGait* h = csg_gaitRead("ramp_written.csv", NULL, &err);
    CS_EXPECT(h && h->ramp == 0.1 + 0.2);
    csg_gaitDestroy(h);
    g->ramp = -1.0; /* the writer refuses an invalid ramp, as the validator does */
    CS_EXPECT(csg_gaitWrite(g, "ramp_bad_written.csv", NULL, &err) == CS_ERR_RANGE &&
              strstr(err.msg, "ramp"));
    CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_ERR_RANGE);
  }
  csg_gaitDestroy(g);
  writeText("ramp_rows.csv", "time,A_II1_O1\n0,0.1\n#@ramp 0\n1,0\n");
  g = csg_gaitRead("ramp_rows.csv", NULL, &err);
  CS_EXPECT(g && g->ramp == 0.0);
  csg_gaitDestroy(g);
  /* made in code: none stated */
  g = csg_gaitCreate(1, &err);
  CS_EXPECT(g && isnan(g->ramp));
  csg_gaitDestroy(g);

  const char* rows = "time,A_II1_O1\n0,0\n";
  char text[256];
#define WITH(line) (snprintf(text, sizeof text, "# c\n%s\n%s", line, rows), text)
  bad("bad_ramp_negative.csv", WITH("# @ramp -0.1"), CS_ERR_RANGE, 2, 0, ">= 0");
  bad("bad_ramp_nan.csv", WITH("# @ramp nan"), CS_ERR_RANGE, 2, 0, "@ramp");
  bad("bad_ramp_inf.csv", WITH("# @ramp inf"), CS_ERR_RANGE, 2, 0, "finite");
  bad("bad_ramp_text.csv", WITH("# @ramp fast"), CS_ERR_PARSE, 2, 0, "'fast'");
  bad("bad_ramp_unit.csv", WITH("# @ramp 0.2 s"), CS_ERR_PARSE, 2, 0, "one number");
  bad("bad_ramp_empty.csv", WITH("# @ramp"), CS_ERR_PARSE, 2, 0, "one number");
  bad("bad_ramp_unknown.csv", WITH("# @rampe 0.2"), CS_ERR_PARSE, 2, 0, "'@rampe'");
  bad("bad_ramp_twice.csv", "# @ramp 0.1\ntime,A_II1_O1\n0,0\n# @ramp 0.1\n", CS_ERR_PARSE, 4, 0,
      "twice");
#undef WITH
}


/* ---- bad input: size limits, checked before memory grows ---- */

static void test_badSize(void) {
  /* one line longer than the default 64 KiB limit */
  size_t n = CSG_DEFAULT_MAX_LINE_BYTES + 100;
  char* big = malloc(n + 64);
  CS_EXPECT(big != NULL);
  if (big) {
    strcpy(big, "time,A_II1_O1\n0,0\n# ");
    size_t k = strlen(big);
    memset(big + k, 'x', n);
    strcpy(big + k + n, "\n1,0\n");
    writeText("bad_long_line.csv", big);
    expectBad("bad_long_line.csv", NULL, CS_ERR_RANGE, 3, 0, "longer than 65536 bytes");
    free(big);
  }
  /* exactly the limit is fine: a comment line of max_line_bytes bytes, CRLF on top */
  csgReadOptions o = csg_defaultReadOptions();
  o.max_line_bytes = 100;
  char text[256];
  snprintf(text, sizeof text, "time\n#%099d\r\n0\n", 0);
  writeText("good_line_limit.csv", text);
  csError err;
  csgGait* g = csg_gaitRead("good_line_limit.csv", &o, &err);
  CS_EXPECT(g != NULL);
  csg_gaitDestroy(g);
  snprintf(text, sizeof text, "time\n#%0100d\n0\n", 0);
  writeText("bad_line_limit.csv", text);
  expectBad("bad_line_limit.csv", &o, CS_ERR_RANGE, 2, 0, "longer than 100 bytes");

  /* more rows than a small limit */
  o = csg_defaultReadOptions();
  o.max_rows = 3;
  writeText("bad_rows_small.csv", "time\n0\n1\n2\n3\n");
  expectBad("bad_rows_small.csv", &o, CS_ERR_RANGE, 5, 0, "more than 3 data rows");

  /* the default row limit, on a file with one row too many */
  FILE* f = fopen("bad_rows_default.csv", "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    fputs("time\n", f);
    for (long i = 0; i <= CSG_DEFAULT_MAX_ROWS; i++) {
      fprintf(f, "%ld\n", i);
    }
    fclose(f);
    expectBad("bad_rows_default.csv", NULL, CS_ERR_RANGE, (int)CSG_DEFAULT_MAX_ROWS + 2, 0,
              "more than 100000 data rows");
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_defaults);
  CS_RUN(test_buildInCode);
  CS_RUN(test_validateRules);
  CS_RUN(test_readGood);
  CS_RUN(test_roundTripRandom);
  CS_RUN(test_badFile);
  CS_RUN(test_badHeader);
  CS_RUN(test_badRows);
  CS_RUN(test_badSize);
  CS_RUN(test_rampDirective);
  return cs_testSummary();
}
