/* test_terrain.c: terrains/terrains_terrain.c: the shipped flat road loads with the geometry
 * of its file, its ODE geoms match the boxes, and every bad input is refused with the right
 * status and a one-line message "<file>:<line>: <cause>" (docs/design.md command-line contract). */
#include "terrains_terrain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"


/* write `text` to `path`, load it and expect status `want` and a message that starts with
 * "<path>:<line>:" and contains `cause` */
static void expectBad(const char* path, const char* text, int line, csStatus want,
                      const char* cause) {
  cs_testWriteText(path, text);
  cstTerrain t;
  csError err;
  cs_errorClear(&err);
  csStatus st = cst_terrainLoad(&t, path, &err);
  char where[300];
  snprintf(where, sizeof where, "%s:%d: ", path, line);
  CS_EXPECT(st == want);
  CS_EXPECT(err.status == want);
  CS_EXPECT(strstr(err.msg, where) == err.msg);
  CS_EXPECT(strstr(err.msg, cause) != NULL);
  CS_EXPECT(strchr(err.msg, '\n') == NULL);
  if (st != want || strstr(err.msg, where) != err.msg || !strstr(err.msg, cause)) {
    fprintf(stderr, "  %s: status %s, message '%s' (wanted '%s...%s')\n", path,
            cs_statusString(st), err.msg, where, cause);
  }
  remove(path);
}


static void test_flatRoad(void) {
  const char* src = getenv("CS_SOURCE_DIR");
  CS_EXPECT(src != NULL);
  char path[512];
  snprintf(path, sizeof path, "%s/terrains/flat_road.terrain", src ? src : ".");
  cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, path, &err) == CS_OK);
  CS_EXPECT(!strcmp(t.name, "flat-road"));
  CS_EXPECT(!strcmp(t.source, path));
  CS_EXPECT(t.nbox == 1);
  /* the file's numbers are exact in binary floating point: compare exactly */
  CS_EXPECT(t.box[0].lo[0] == 0 && t.box[0].hi[0] == 600);   /* 600 mm long */
  CS_EXPECT(t.box[0].lo[2] == 0 && t.box[0].hi[2] == 300);   /* 300 mm wide */
  CS_EXPECT(t.box[0].hi[1] == 0 && t.box[0].lo[1] < 0);      /* top at y = 0 */
  CS_EXPECT(t.start[0] == 150 && t.start[1] == 117.5);
  CS_EXPECT(t.heading_deg == 0);
  CS_EXPECT(cst_terrainHeightAt(&t, t.start[0], t.start[1]) == 0);
  CS_EXPECT(cst_terrainHeightAt(&t, -1, 100) == -INFINITY); /* off the road */
}


static void test_goodFile(void) {
  /* a step road: the higher box wins where they overlap; comments, CRLF, tabs, heading */
  cs_testWriteText("terrain_step.terrain",
            "# step road\r\nname step\t# trailing comment\r\n\r\n"
            "box 0 -20 0  600 0 300\r\nbox 300 -20 0 600 25 300\r\n"
            "start 150 117.5\r\nheading -90\r\n");
  cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, "terrain_step.terrain", &err) == CS_OK);
  CS_EXPECT(!strcmp(t.name, "step") && t.nbox == 2 && t.heading_deg == -90);
  CS_EXPECT(cst_terrainHeightAt(&t, 100, 100) == 0);
  CS_EXPECT(cst_terrainHeightAt(&t, 400, 100) == 25);
  /* no name, no trailing newline, a 63-character name is the longest allowed */
  cs_testWriteText("terrain_noname.terrain", "box 0 -1 0 10 0 10\nstart 5 5");
  CS_EXPECT(cst_terrainLoad(&t, "terrain_noname.terrain", &err) == CS_OK);
  CS_EXPECT(!strcmp(t.name, "unnamed") && t.start[1] == 5);
  char text[256];
  snprintf(text, sizeof text, "name %063d\nbox 0 -1 0 10 0 10\nstart 5 5\n", 7);
  cs_testWriteText("terrain_name63.terrain", text);
  CS_EXPECT(cst_terrainLoad(&t, "terrain_name63.terrain", &err) == CS_OK);
  CS_EXPECT(strlen(t.name) == 63);
  remove("terrain_step.terrain");
  remove("terrain_noname.terrain");
  remove("terrain_name63.terrain");
}


static void test_buildOde(void) {
  cstTerrain t;
  csError err;
  cs_testWriteText("terrain_ode.terrain",
            "box 0 -20 0 600 0 300\nbox 300 0 0 600 25 300\nbox -10 -5 -10 0 5 0\nstart 1 1\n");
  CS_EXPECT(cst_terrainLoad(&t, "terrain_ode.terrain", &err) == CS_OK);
  remove("terrain_ode.terrain");
  dInitODE2(0);
  dSpaceID space = dSimpleSpaceCreate(0);
  CS_EXPECT(cst_terrainBuildOde(&t, space) == t.nbox);
  CS_EXPECT(dSpaceGetNumGeoms(space) == 3);
  /* each geom is a static box with the file's centre and size (sums of small integers and
   * halves: exact in double) */
  for (int i = 0; i < dSpaceGetNumGeoms(space) && i < t.nbox; i++) {
    dGeomID g = dSpaceGetGeom(space, i);
    CS_EXPECT(dGeomGetClass(g) == dBoxClass);
    CS_EXPECT(dGeomGetBody(g) == 0);
    const dReal* c = dGeomGetPosition(g);
    dVector3 len;
    dGeomBoxGetLengths(g, len);
    /* ODE's simple space may list its geoms in any order: find the box with this centre */
    int found = 0;
    for (int k = 0; k < t.nbox; k++) {
      const cstBox* b = &t.box[k];
      int same = 1;
      for (int j = 0; j < 3; j++) {
        same = same && c[j] == 0.5 * (b->lo[j] + b->hi[j]) && len[j] == b->hi[j] - b->lo[j];
      }
      found += same;
    }
    CS_EXPECT(found == 1);
  }
  dSpaceDestroy(space);
  dCloseODE();
}


static void test_badFiles(void) {
  /* missing file: no line to name, the cause is the system's */
  remove("terrain_missing.terrain");
  cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, "terrain_missing.terrain", &err) == CS_ERR_IO);
  CS_EXPECT(strstr(err.msg, "terrain_missing.terrain: cannot open terrain file: ") == err.msg);
  CS_EXPECT(strstr(err.msg, "No such file") != NULL);

  const char* ok = "box 0 -20 0 600 0 300\n";
  char text[4096];
  expectBad("terrain_unknown.terrain", "# x\nbox 0 -20 0 600 0 300\nstaart 150 117.5\n", 3,
            CS_ERR_PARSE, "unknown statement 'staart'");
  expectBad("terrain_box5.terrain", "box 0 -20 0 600 0\nstart 1 1\n", 1, CS_ERR_PARSE,
            "'box' needs 6 numbers x0 y0 z0 x1 y1 z1 (mm), got 5 values");
  expectBad("terrain_box7.terrain", "box 0 -20 0 600 0 300 7\n", 1, CS_ERR_PARSE,
            "got 7 values");
  expectBad("terrain_boxjunk.terrain", "\nbox 0 -20 0 600 0 30x\n", 2, CS_ERR_PARSE,
            "'box' value 6 '30x' is not a number");
  expectBad("terrain_boxword.terrain", "box 0 -20 zero 600 0 300\n", 1, CS_ERR_PARSE,
            "'box' value 3 'zero' is not a number");
  expectBad("terrain_inverted.terrain", "box 600 -20 0 0 0 300\n", 1, CS_ERR_RANGE,
            "box corners must satisfy x0<x1, y0<y1, z0<z1");
  expectBad("terrain_flat.terrain", "box 0 0 0 600 0 300\n", 1, CS_ERR_RANGE,
            "box corners must satisfy");
  /* non-finite numbers: strtod accepts these, the parser must not */
  expectBad("terrain_nan.terrain", "box 0 -20 0 nan 0 300\n", 1, CS_ERR_RANGE,
            "'box' value 4 'nan' is not a finite number");
  expectBad("terrain_inf.terrain", "box -inf -20 0 600 0 300\n", 1, CS_ERR_RANGE,
            "'box' value 1 '-inf' is not a finite number");
  expectBad("terrain_huge.terrain", "box 0 -20 0 1e999 0 300\n", 1, CS_ERR_RANGE,
            "'box' value 4 '1e999' is not a finite number");
  expectBad("terrain_startnan.terrain", "box 0 -20 0 600 0 300\nstart NaN 1\n", 2, CS_ERR_RANGE,
            "'start' value 1 'NaN' is not a finite number");
  expectBad("terrain_far.terrain", "box 0 -20 0 1e300 0 300\n", 1, CS_ERR_RANGE,
            "box coordinate 1e+300 mm is beyond");
  /* too many boxes: the 33rd */
  text[0] = '\0';
  for (int i = 0; i <= CST_MAX_BOXES; i++) {
    strcat(text, ok);
  }
  expectBad("terrain_many.terrain", text, CST_MAX_BOXES + 1, CS_ERR_RANGE, "more than 32 boxes");
  /* whole-file checks name the last line */
  expectBad("terrain_nostart.terrain", "name x\nbox 0 -20 0 600 0 300\n# end\n", 3, CS_ERR_PARSE,
            "without a 'start' statement");
  expectBad("terrain_nobox.terrain", "name x\nstart 1 1\n", 2, CS_ERR_PARSE,
            "without a 'box' or 'heightfield' statement");
  expectBad("terrain_empty.terrain", "", 1, CS_ERR_PARSE, "without a 'box' or 'heightfield' statement");
  expectBad("terrain_outside.terrain", "box 0 -20 0 600 0 300\nstart 700 117.5\n\n", 2,
            CS_ERR_RANGE, "start (700, 117.5) is not above any box");
  expectBad("terrain_start3.terrain", "start 1 2 3\n", 1, CS_ERR_PARSE,
            "'start' needs 2 numbers x z (mm), got 3 values");
  expectBad("terrain_start2x.terrain", "start 1 2\nstart 3 4\n", 2, CS_ERR_PARSE,
            "second 'start' (the first is on line 1)");
  /* overlong line: 1023 characters fit, 1024 do not */
  memset(text, ' ', 1100);
  memcpy(text, "box 0 -20 0 600 0 300", 21);
  text[1023] = '\n';
  strcpy(text + 1024, "start 1 1\n");
  cs_testWriteText("terrain_line1023.terrain", text);
  CS_EXPECT(cst_terrainLoad(&t, "terrain_line1023.terrain", &err) == CS_OK);
  remove("terrain_line1023.terrain");
  memset(text, ' ', 1100);
  memcpy(text, "# a comment\nbox 0 -20 0 600 0 300", 33);
  text[12 + 1024] = '\n';
  strcpy(text + 12 + 1025, "start 1 1\n");
  expectBad("terrain_long.terrain", text, 2, CS_ERR_RANGE, "line longer than 1023 bytes");
  expectBad("terrain_heading.terrain", "box 0 -20 0 600 0 300\nstart 1 1\nheading\n", 3,
            CS_ERR_PARSE, "'heading' needs 1 number (degrees), got 0 values");
  expectBad("terrain_headingx.terrain", "heading north\n", 1, CS_ERR_PARSE,
            "'heading' value 1 'north' is not a number");
  expectBad("terrain_headinginf.terrain", "heading inf\n", 1, CS_ERR_RANGE,
            "'heading' value 1 'inf' is not a finite number");
  expectBad("terrain_heading1e9.terrain", "heading 1e9\n", 1, CS_ERR_RANGE,
            "heading 1e+09 deg is beyond");
  /* names: one word of at most 63 characters, never cut short */
  snprintf(text, sizeof text, "name %064d\n%sstart 1 1\n", 7, ok);
  expectBad("terrain_name64.terrain", text, 1, CS_ERR_RANGE, "name longer than 63 characters");
  expectBad("terrain_name2.terrain", "name flat road\n", 1, CS_ERR_PARSE,
            "'name' needs one word, got 2");
  expectBad("terrain_name0.terrain", "\n\nname   # nothing\n", 3, CS_ERR_PARSE,
            "'name' needs one word, got 0");
  /* a NUL byte: binary data is not a terrain file */
  FILE* f = fopen("terrain_nul.terrain", "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    fwrite("box 0 -20 0 600 0 300\nstart 1\0 1\n", 1, 33, f);
    fclose(f);
  }
  CS_EXPECT(cst_terrainLoad(&t, "terrain_nul.terrain", &err) == CS_ERR_PARSE);
  CS_EXPECT(strstr(err.msg, "terrain_nul.terrain:2: byte 8: NUL byte") == err.msg);
  remove("terrain_nul.terrain");
}


/* oriented boxes, friction per surface and the slope: what the file says, and the ground
 * height on an incline against its closed form */
static void test_inclinesAndFriction(void) {
  cs_testWriteText("terrain_incline.terrain",
            "name incline\n"
            "box 0 -20 0 100 0 100 mu 0.3\n"
            "# a ramp: 200 long, 20 thick, 100 wide, turned 15 deg about z (10 cos 15 = 9.659)\n"
            "obox 200 -9.6592582628906829 50  200 20 100  0 0 1 15 mu 1.2\n"
            "slope -12.5\n"
            "start 50 50\n");
  cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, "terrain_incline.terrain", &err) == CS_OK);
  CS_EXPECT(t.nbox == 2 && t.has_mu);
  CS_EXPECT(!t.box[0].oriented && t.box[0].own_mu && t.box[0].mu == 0.3);
  CS_EXPECT(t.box[1].oriented && t.box[1].own_mu && t.box[1].mu == 1.2);
  CS_EXPECT(cst_terrainBoxMu(&t, 0, 0.8) == 0.3 && cst_terrainBoxMu(&t, 1, 0.8) == 1.2);
  CS_EXPECT(t.slope_deg == -12.5);
  double g[3];
  cst_terrainGravityDir(&t, g);
  /* 1e-15: round-off of sin and cos */
  CS_EXPECT_NEAR(g[0], sin(12.5 * 3.14159265358979323846 / 180), 1e-15, 0);
  CS_EXPECT_NEAR(g[1], -cos(12.5 * 3.14159265358979323846 / 180), 1e-15, 0);
  /* the ramp's top face: the plane through its top centre c + 10 n (n = (-sin 15, cos 15, 0),
   * its normal) rising at tan 15 deg; checked at three points, 1e-9 mm of round-off */
  double th = 15 * 3.14159265358979323846 / 180;
  double top[2] = {200 - 10 * sin(th), -9.6592582628906829 + 10 * cos(th)};
  for (int i = -1; i <= 1; i++) {
    double x = 200 + 60 * i;
    CS_EXPECT_NEAR(cst_terrainHeightAt(&t, x, 50), top[1] + tan(th) * (x - top[0]), 1e-9, 0);
  }
  /* beyond its length and its width: not on the ramp */
  CS_EXPECT(!isfinite(cst_terrainHeightAt(&t, 320, 50)));
  CS_EXPECT(!isfinite(cst_terrainHeightAt(&t, 200, 120)));
  /* a zeroed box keeps the run's friction */
  CS_EXPECT(!t.box[0].oriented);
  cstTerrain z;
  memset(&z, 0, sizeof z);
  z.nbox = 1;
  CS_EXPECT(cst_terrainBoxMu(&z, 0, 0.8) == 0.8);
  remove("terrain_incline.terrain");

  expectBad("terrain_mu.terrain", "box 0 -20 0 600 0 300 mu -0.1\nstart 1 1\n", 1, CS_ERR_RANGE,
            "'box' friction -0.1 must be in 0..10");
  expectBad("terrain_mu2.terrain", "box 0 -20 0 600 0 300 mu nan\nstart 1 1\n", 1, CS_ERR_RANGE,
            "friction 'nan' is not a finite number");
  expectBad("terrain_mu3.terrain", "box 0 -20 0 600 0 300 nu 0.5\nstart 1 1\n", 1, CS_ERR_PARSE,
            "got 8 values");
  expectBad("terrain_obox.terrain", "obox 0 0 0 10 10 10 0 0 1\nstart 0 0\n", 1, CS_ERR_PARSE,
            "'obox' needs 10 numbers");
  expectBad("terrain_obox2.terrain", "obox 0 0 0 10 0 10 0 0 1 5\nstart 0 0\n", 1, CS_ERR_RANGE,
            "obox edge lengths must be > 0");
  expectBad("terrain_obox3.terrain", "obox 0 0 0 10 10 10 0 0 0 5\nstart 0 0\n", 1,
            CS_ERR_RANGE, "obox rotation axis must not be zero");
  expectBad("terrain_obox4.terrain", "obox 0 0 0 10 10 10 0 0 1 400\nstart 0 0\n", 1,
            CS_ERR_RANGE, "obox angle beyond");
  expectBad("terrain_slope.terrain", "box 0 -20 0 600 0 300\nslope 46\nstart 1 1\n", 2,
            CS_ERR_RANGE, "slope 46 deg is beyond +-45 deg");
  expectBad("terrain_slope2.terrain", "box 0 -20 0 600 0 300\nslope 5\nslope 6\nstart 1 1\n", 3,
            CS_ERR_PARSE, "second 'slope' (the first is on line 2)");
}


/* a heightfield: read as written, its height on ODE's triangles, and its errors */
static void test_heightfield(void) {
  cs_testWriteText("terrain_hf.terrain",
            "name bumps\nheightfield -10 0 10 20 3 2 mu 0.5\n"
            "row 0 1 2   # z = 0\nrow 4 5 6   # z = 20\nstart 0 10\n");
  static cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, "terrain_hf.terrain", &err) == CS_OK);
  CS_EXPECT(t.has_hf && t.nbox == 0 && t.has_mu && t.hf.own_mu && t.hf.mu == 0.5);
  CS_EXPECT(t.hf.nx == 3 && t.hf.nz == 2 && t.hf.hmin == 0 && t.hf.hmax == 6);
  CS_EXPECT(t.hf.h[4] == 5); /* sample (1, 1) */
  /* cell (0, 0): A = 0 at (-10, 0), B = 1 at (0, 0), C = 4 at (-10, 20), D = 5 at (0, 20);
   * the diagonal B-C: at (-7.5, 5) (ABC) 0 + 0.25 + 0.25 * 4 = 1.25; at (-2.5, 15) (DBC)
   * 5 + (1 - 5)(1 - 0.75) + (4 - 5)(1 - 0.75) = 3.75; exact in binary */
  CS_EXPECT(cst_terrainHeightAt(&t, -7.5, 5) == 1.25);
  CS_EXPECT(cst_terrainHeightAt(&t, -2.5, 15) == 3.75);
  CS_EXPECT(!isfinite(cst_terrainHeightAt(&t, 10.5, 5)));
  remove("terrain_hf.terrain");
  expectBad("terrain_hf1.terrain", "heightfield 0 0 10 10 3 2\nrow 0 0 0\nstart 5 5\n", 3,
            CS_ERR_PARSE, "after 1 of the heightfield's 2 rows (line 1)");
  expectBad("terrain_hf2.terrain", "heightfield 0 0 10 10 3 2\nrow 0 0\n", 2, CS_ERR_PARSE,
            "'row' needs 3 numbers");
  expectBad("terrain_hf3.terrain", "row 0 0\n", 1, CS_ERR_PARSE, "'row' before 'heightfield'");
  expectBad("terrain_hf4.terrain", "heightfield 0 0 10 10 65 2\n", 1, CS_ERR_RANGE,
            "sample counts whole numbers in 2..64");
  expectBad("terrain_hf5.terrain", "heightfield 0 0 10 10 2.5 2\n", 1, CS_ERR_RANGE,
            "sample counts whole numbers");
  expectBad("terrain_hf6.terrain", "heightfield 0 0 0 10 2 2\n", 1, CS_ERR_RANGE,
            "spacing must be > 0");
  expectBad("terrain_hf7.terrain",
            "heightfield 0 0 10 10 2 2\nrow 0 0\nrow 0 0\nrow 0 0\n", 4, CS_ERR_PARSE,
            "'row' beyond the heightfield's nz rows");
  expectBad("terrain_hf8.terrain",
            "heightfield 0 0 10 10 2 2\nrow 0 0\nrow 0 nan\n", 3, CS_ERR_RANGE,
            "not a finite number");
  expectBad("terrain_hf9.terrain",
            "heightfield 0 0 10 10 2 2\nrow 0 0\nrow 0 0\nheightfield 0 0 1 1 2 2\n", 4,
            CS_ERR_PARSE, "second 'heightfield' (the first is on line 1)");
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_flatRoad);
  CS_RUN(test_goodFile);
  CS_RUN(test_buildOde);
  CS_RUN(test_badFiles);
  CS_RUN(test_inclinesAndFriction);
  CS_RUN(test_heightfield);
  return cs_testSummary();
}
